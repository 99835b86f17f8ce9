#pragma once
// The legal-set properties of VLayer[MC] (issue 4 names), each a check of its own:
//
//   l1mc-closure    L1MC (Def 7.1) is closed under steps and ticks (seed 000 §3.1, line 1220
//                   "it is routine to check that L1MC is indeed a legal set"), checked from
//                   every L1MC state that the instance reaches through L1MC states;
//   reset-in-l1mc   ResetMC ⊆ L1MC (Def 7.2(1)), checked on the instance's reachable states
//                   and on the ResetMC states of `reset_family` (models/vlayer_mc/lmc.hpp);
//   lmc-closure     LMC, the states reachable from ResetMC (line 1248), is a legal set: closed
//                   by construction under the steps explored; checked: LMC ⊆ L1MC and no LMC
//                   state is stuck.
//
// Each result carries a `covered` figure saying which states were checked: L1MC and ResetMC
// have far too many valuations to enumerate (models/vlayer_mc/README.md, "State count").

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/l1mc.hpp"

namespace vlayer_mc {

// `system` is VLayer[MC] of `config` with its start set (the instance).
checker::PropertyResult check_l1mc_closure(const VlConfig& config, const tioa::Automaton& system,
                                           MWindow window, const checker::ExploreOptions& options);
checker::PropertyResult check_reset_in_l1mc(const VlConfig& config, const tioa::Automaton& system,
                                            MWindow window, const checker::ExploreOptions& options);
// `layer` is VLayer[MC] of `config`; LMC is explored from `reset_family(config, layer)`.
checker::PropertyResult check_lmc_closure(const VlConfig& config, const tioa::Automaton& layer,
                                          MWindow window, const checker::ExploreOptions& options);

// For a run that fails or is not confirmed: the variant parameters still off (the paper's version),
// the decision of the README each stands for, and the clauses of Def 7.1 it repairs.
void note_repairs(const VlConfig& config, checker::PropertyResult& result);

// A note line when δ breaks the round-length rule of §5.5 (line 981), else nothing.
void note_round_length(const VlConfig& config, checker::PropertyResult& result);

} // namespace vlayer_mc
