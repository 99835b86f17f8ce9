#pragma once
// Lemma 7.3 of seed 000 (journal), on VLayer[MC].
//
// Seed 000 (journal), §7.2, lines 1265–1268:
//   "LEMMA 7.3. VLNodes[MC] is self-stabilizing to L1_MC in time t > ε_sample relative to
//    the automaton R(Vbcast‖RW‖VW)."
// (Extraction: "L1" and "MC" stand on two lines, read L1_MC; "εsample" is read ε_sample; the
// hyphenated "rel-ative" is joined.)
//
// Checked as: VLNodes[MC] started anywhere (U) with R(Vbcast‖RW‖VW) is in L1MC from
// any time t > ε_sample on. The least whole t (quanta) is measured with
// checker::check_stabilisation and judged against the bound ε_sample + 1. A time above
// the bound is a counterexample (L1MC is decided exactly), given with the clauses of
// Def 7.1 that the last state outside L1MC breaks. Faults and start states:
// proofs/vlayer_mc/stabilisation_common.hpp.

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"

namespace vlayer_mc {

checker::PropertyResult check_lemma_7_3(const VlConfig& config, MWindow window,
                                        const ArbitraryStarts& starts,
                                        const checker::ExploreOptions& options);

} // namespace vlayer_mc
