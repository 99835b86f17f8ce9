#pragma once
// `sweep`: one model's properties over a range of one whole-number parameter (a seed of
// generated instances, a size), one row per value, as a verdict table; with --save, each
// instance where a property is violated is written as a file the model reads back
// (ModelDefinition::instance_file), with the command that reproduces it.

#include <cstdint>
#include <string>

#include "catalogue/registry.hpp"
#include "cli/settings.hpp"

namespace cli {

struct SweepSettings {
  std::string over;     // "seed=1..20"
  std::string save_dir; // empty: save nothing
};

int command_sweep(const catalogue::Catalogue& models, const ModelRequest& request,
                  const SweepSettings& sweep, const RunSettings& settings);

} // namespace cli
