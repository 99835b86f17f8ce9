#pragma once
// Lemma 7.4 of seed 000 (journal), on VLayer[MC].
//
// Seed 000 (journal), §7.2, lines 1279–1282:
//   "LEMMA 7.4. Executions of VLayer[MC] started in states in L1_MC stabilize in time
//    δ + d + e to executions started in states in LMC."
// (Extraction: "L1" and "MC" stand on two lines, read L1_MC.)
//
// Checked as: executions started in the L1MC states reached (from the instance, and from the
// start states of Lemma 7.3) are in LMC from time δ + d + e on. "In LMC" is measured as the
// first state in ResetMC (or the known part of LMC, D29), an upper bound on the time into
// LMC: a time above the bound is "not confirmed", not a counterexample. Faults, "in LMC" and
// start states: proofs/vlayer_mc/stabilisation_common.hpp.

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"

namespace vlayer_mc {

checker::PropertyResult check_lemma_7_4(const VlConfig& config, MWindow window,
                                        const ArbitraryStarts& starts,
                                        const checker::ExploreOptions& options);

} // namespace vlayer_mc
