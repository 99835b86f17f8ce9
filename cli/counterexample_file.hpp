#pragma once
// --counterexample-out FILE (check): the first counterexample of a run that is an instance
// of its own, written as the file that reproduces it. Today the round-level lemmas of
// mc-round give one: a round configuration (models/mc/round_config.hpp) that
// `round --config FILE` runs and `check mc-round -p config=FILE` checks again.

#include <fstream>
#include <optional>
#include <string>

#include "cli/model_run.hpp"

namespace cli {

// Writes the "config" of the first witness with role "counterexample" (in the order of the
// properties) to `file`; one line on stderr names the property and the claim.
// With no such counterexample, removes the file and says so on stderr. Throws
// catalogue::UsageError when the file cannot be written.
void write_counterexample_file(std::optional<std::ofstream>& file, const std::string& path,
                               const ModelRun& run);

} // namespace cli
