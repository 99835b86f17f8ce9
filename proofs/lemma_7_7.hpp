#pragma once
// Lemma 7.7 of seed 000 (journal), on VLayer[MC] with the relation R_MC
// (models/vlayer_mc/rmc_relation.hpp).
//
// Seed 000 (journal), §7.3, lines 1328–1329:
//   "LEMMA 7.7. For each state x ∈ ResetMC, there exists a state y ∈ Reach_VLayer[MC] such
//    that x R_MC y."
// (Extraction: "ReachVLayer[MC]" is read Reach_VLayer[MC] and "xRMCy" x R_MC y, the
// subscripts run into the words.)
//
// Checked on the `reset_family` ResetMC states (models/vlayer_mc/lmc.hpp; not all of
// ResetMC), Reach being every state reachable in VLayer[MC] with failures and restarts of
// robots and VSAs (the paper's VLayer[MC], whatever `layer`'s Faults), from every placement
// of the robots with no node failed (proofs/vlayer_mc/rmc_matching.hpp). Holds iff every
// family state has a related reachable state; the figures count the matched family states in
// every reading of R_MC.

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/rmc_relation.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// With R_MC in the loose reading.
checker::PropertyResult check_lemma_7_7(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options);

// With R_MC in another reading.
checker::PropertyResult check_lemma_7_7(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options,
                                        RmcReading reading);

} // namespace vlayer_mc
