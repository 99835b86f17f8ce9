#pragma once
// A configuration of the round-level system as a JSON file: what `tioa-check round --config`
// runs, what `-p config=PATH` of mc-round checks the lemmas on, and what a counterexample
// is written as (`--counterexample-out`), so that each reproduces with the other two:
//
//   {"m": 2, "nbh": 4, "k": 1, "rho1": "1/2", "rho2": "9/10",
//    "q":      [[0, 1], [1, 3]],
//    "robots": [[5, 0], [0, 2]]}
//
// q[i][j] and robots[i][j] are region row i (row 0 at the top), column j; rationals are
// strings holding exact numbers ("9/10", "0.9").

#include <iosfwd>
#include <string>

#include "models/mc/curve_file.hpp"
#include "models/mc/round.hpp"

namespace mc {

// The largest grid side m a configuration may give: the grid keeps m⁴ distances; the
// paper's runs use m <= 20.
inline constexpr int max_config_side = 50;

struct RoundConfig {
  RoundSystem system;
  Counts robots;
};

// Throws std::invalid_argument with one line "round config '<source>': <what>", naming the
// field, on anything wrong. With `curve` (a curve file, `round --curve-file`): its q instead
// of the field "q", which may then be left out; its m must be the configuration's.
RoundConfig read_round_config(std::istream& in, const std::string& source,
                              const CurveFile* curve = nullptr);
// The file `path` (at most 16 MiB, a text file), read as above.
RoundConfig read_round_config_file(const std::string& path, const CurveFile* curve = nullptr);

// The configuration as a file that read_round_config reads back to it: one field a line,
// each matrix row on one line.
std::string round_config_json(const RoundSystem& system, const Counts& robots);

} // namespace mc
