#pragma once
// Lemma 7.6 of seed 000 (journal), on VLayer[MC] with the relation R_MC
// (models/vlayer_mc/rmc_relation.hpp).
//
// Seed 000 (journal), §7.3, line 1321:
//   "LEMMA 7.6. R_MC is a simulation relation for VLayer[MC]."
// (Extraction: "RMC" is read R_MC.)
//
// Checked on the pairs reachable from Lemma 7.7's (proofs/lemma_7_7.hpp): (x, y) with x a
// family state and y each related reachable state (proofs/vlayer_mc/rmc_matching.hpp). For
// each pair and each step x −a→ x′ of `layer` (its own Faults: without faults, the system
// after the last failure), some step y −a→ y′ of VLayer[MC] with failures, with the same
// label (internal actions too), has x′ R_MC y′; every such (x′, y′) is explored
// (checker::search_simulation). Ticks are steps of one quantum.

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/rmc_relation.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// With R_MC in the loose reading.
checker::PropertyResult check_lemma_7_6(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options);

// With R_MC in another reading.
checker::PropertyResult check_lemma_7_6(const VlConfig& config, const tioa::Automaton& layer,
                                        MWindow window, const checker::ExploreOptions& options,
                                        RmcReading reading);

} // namespace vlayer_mc
