#pragma once
// Reach and the ResetMC family, matched by R_MC (models/vlayer_mc/rmc_relation.hpp): the
// search that Lemmas 7.6 and 7.7 (proofs/lemma_7_6.hpp, proofs/lemma_7_7.hpp) both start from,
// and the figures and notes both report. Reach is
// every state reachable in VLayer[MC] with failures and restarts of robots and VSAs, from
// every placement of the robots with no node failed; each state of the `reset_family`
// (models/vlayer_mc/lmc.hpp) is compared with the reachable states of the same
// RmcRelation::key only.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/rmc_relation.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "tioa/automaton.hpp"
#include "tioa/start_set.hpp"

namespace vlayer_mc {

// VLayer[MC] as the paper has it: VW fails and restarts VSAs, robots fail and restart.
inline constexpr Faults reach_faults{.robots = true, .vsas = true};

// Every reading of R_MC, in the order of Matching::matched.
inline constexpr std::array<RmcReading, 3> readings{RmcReading::strict, RmcReading::loose,
                                                    RmcReading::loose_reg};

// Every placement of the robots, no node failed, every other variable at its initial value.
tioa::StartSet every_placement(const VlConfig& config, const tioa::Automaton& layer);

// Both automata are VLayer[MC] of the same config: the same variables and actions (a
// ModelError otherwise).
void require_same_layer(const tioa::Automaton& a, const tioa::Automaton& b);

struct Matching {
  explicit Matching(std::uint32_t words) : reach(words) {}
  checker::Exploration reach;
  std::vector<std::vector<tioa::Word>> family;
  // Per family state: its related reachable states.
  std::vector<std::vector<checker::StateId>> related;
  std::vector<std::array<bool, 3>> matched; // per family state and reading: some related y
  std::uint64_t in_reset_mc = 0;
};

// Reach of `full` (VLayer[MC] with reach_faults) within `options`, the family states of
// `layer` and how many of them meet Def 7.2 with `window`; when Reach is complete, each family
// state's related reachable states in `reading`, and whether it has one in each reading.
Matching match_family(const VlConfig& config, const tioa::Automaton& layer,
                      const tioa::Automaton& full, MWindow window,
                      const checker::ExploreOptions& options, RmcReading reading);

// The reachable state that breaks the fewest conditions of R_MC with x, and what it breaks.
std::pair<checker::StateId, std::vector<std::string>>
closest(const RmcRelation& relation, const checker::Exploration& reach, const tioa::Word* x);

// What the figure `covered` of Lemmas 7.6 and 7.7 says of the family.
std::string family_figure(const VlConfig& config, const Matching& m);

// The notes of Lemmas 7.6 and 7.7: the reading of R_MC and of Def 7.1(2), and the
// round-length warning (proofs/vlayer_mc/legal_sets.hpp).
void note_rmc_reading(const VlConfig& config, MWindow window, RmcReading reading,
                      checker::PropertyResult& result);

} // namespace vlayer_mc
