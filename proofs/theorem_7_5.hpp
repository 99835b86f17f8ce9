#pragma once
// Theorem 7.5 of seed 000 (journal), on VLayer[MC].
//
// Seed 000 (journal), §7.2, lines 1295–1296:
//   "THEOREM 7.5. VLNodes[MC] is self-stabilizing to LMC in time δ + d + e + ε_sample
//    relative to R(Vbcast‖RW‖VW)."
// (Extraction: "εsample" is read ε_sample.) The text before it (lines 1290–1293) says "From
// transitivity of stabilization and 7.4, the next result follows": Lemma 3.4 (line 442).
//
// Checked as: U(VLNodes) ‖ R(Vbcast‖RW‖VW) is in LMC from δ + d + e + ε_sample on, measured
// directly (an upper bound on the time into LMC, as in Lemma 7.4: a time above the bound is
// "not confirmed") and through Lemma 3.4: the measured t1 (start -> L1MC, as Lemma 7.3) and
// t2 (L1MC -> LMC, as Lemma 7.4) must give t ≤ t1 + t2, else the verdict is violated. Faults,
// "in LMC" and start states: proofs/vlayer_mc/stabilisation_common.hpp.

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"

namespace vlayer_mc {

checker::PropertyResult check_theorem_7_5(const VlConfig& config, MWindow window,
                                          const ArbitraryStarts& starts,
                                          const checker::ExploreOptions& options);

} // namespace vlayer_mc
