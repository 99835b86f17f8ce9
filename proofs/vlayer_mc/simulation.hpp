#pragma once
// The checks of seed 000 §7.3 (lines 1300–1335) for the simulation relation R_MC
// (models/vlayer_mc/rmc_relation.hpp):
//
//   LEMMA 7.6. R_MC is a simulation relation for VLayer[MC].                  (line 1323)
//   LEMMA 7.7. For each state x ∈ ResetMC, there exists a state y ∈ Reach_VLayer[MC]
//              such that x R_MC y.                                             (line 1330)
//
// Both start from Reach and the ResetMC family matched by R_MC
// (proofs/vlayer_mc/rmc_matching.hpp).

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/rmc_relation.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// Lemma 7.7 on the `reset_family` ResetMC states (models/vlayer_mc/lmc.hpp; not all of ResetMC),
// Reach being every state reachable in VLayer[MC] with failures and restarts of robots and
// VSAs (the paper's VLayer[MC], whatever `layer`'s Faults), from every placement of the
// robots with no node failed. Holds iff every family state has a related reachable state.
checker::PropertyResult check_lemma_7_7(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options);

// Lemma 7.6 on the pairs reachable from Lemma 7.7's: (x, y) with x a family state and y each
// related reachable state. For each pair and each step x −a→ x′ of `layer` (its own Faults:
// without faults, the system after the last failure), some step y −a→ y′ of VLayer[MC] with
// failures, with the same label (internal actions too), has x′ R_MC y′; every such (x′, y′)
// is explored. Ticks are steps of one quantum.
checker::PropertyResult check_lemma_7_6(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options);

// The same with R_MC in another reading (the ones above use RmcReading::loose).
checker::PropertyResult check_lemma_7_7(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options,
                                        RmcReading reading);
checker::PropertyResult check_lemma_7_6(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options,
                                        RmcReading reading);

} // namespace vlayer_mc
