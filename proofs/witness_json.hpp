#pragma once
// The structured form of the counterexamples that are not traces of an automaton (a round
// of mc-round's lemmas, a run to the fixed point, a matrix of Lemma 6.8, a run with
// positions): JSON objects that --json reports (`witnesses`) and --trace-out writes. Grids are
// lists of rows, row 0 at the top as the text reports print them; a region is [row, col]; rationals
// are strings
// ("9/10").

#include <nlohmann/json.hpp>

#include "proofs/family.hpp"

namespace proofs {

using Json = nlohmann::ordered_json;

Json region_json(int m, RegionId u);
Json grid_json(int m, const std::vector<std::int64_t>& values);
// {"m", "neighbourhood", "curve", "q" (a grid, units of sigma, 0 off the curve), "k", "rho1",
// "rho2"}
Json setting_json(const Setting& setting);
Json flow_json(int m, const mc::Flow& flow);
// The setting with these counts as a round configuration (models/mc/round_config.hpp):
// {"m", "nbh", "k", "rho1", "rho2", "q", "robots"}, what `round --config` runs and
// `-p config=` checks; a counterexample carries it as "config" (--counterexample-out).
Json config_json(const Setting& setting, const Counts& robots);

} // namespace proofs
