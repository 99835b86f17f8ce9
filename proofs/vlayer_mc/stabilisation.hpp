#pragma once
// The stabilisation results of seed 000 §7.2 (lines 1264–1290) on VLayer[MC]:
//
//   lemma-7.3    VLNodes[MC] started anywhere (U) with R(Vbcast‖RW‖VW) is in L1MC from any
//                time t > ε_sample on: measured as the least whole t (quanta), bound
//                ε_sample + 1;
//   lemma-7.4    executions started in L1MC are in LMC from time δ + d + e on;
//   theorem-7.5  U(VLNodes) ‖ R(Vbcast‖RW‖VW) is in LMC from δ + d + e + ε_sample on, measured
//                directly and through Lemma 3.4 (t ≤ t1 + t2).
//
// Faults: the lemmas speak of executions after t0, the last failure or restart (§7, line
// 1340). The system has no fault actions enabled (D13) and U(VLNodes) lets every `failed`
// flag start true or false: any fault history before t0 leaves such a state.
//
// "In LMC": LMC is the set of states reachable from ResetMC (line 1248), so an execution is in
// LMC from the first time it is in a ResetMC state on. The checks measure that time: ResetMC
// states are `settled` (checker::check_stabilisation). It bounds the time into LMC from
// above (a state may lie in LMC without its own execution passing through ResetMC), so a
// measured time within the bound confirms the lemma; one above it is reported with its
// witness as "not confirmed", not as a violation.
//
// Start states: U(VLNodes) ‖ R(env) has every valuation of the nodes' variables (about 10^9
// on a 1×1 grid with one robot) times the reachable states of the environment. Below
// `exhaustive_limit` start states all are explored; above it a seeded random sample of
// `samples` of them is, and a bound that holds on all of them gives "incomplete" (a bound
// broken on one of them is a real counterexample). The environment's reachable states are
// listed when there are at most `environment_limit` (1×1 with one robot has 3.5 million:
// VBcast may hold any message), else each sample ends a seeded random walk in it. The
// figure `covered` says which.

#include <cstdint>

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"

namespace vlayer_mc {

checker::PropertyResult check_lemma_7_3(const VlConfig& config, MWindow window,
                                        const ArbitraryStarts& starts,
                                        const checker::ExploreOptions& options);
checker::PropertyResult check_lemma_7_4(const VlConfig& config, MWindow window,
                                        const ArbitraryStarts& starts,
                                        const checker::ExploreOptions& options);
checker::PropertyResult check_theorem_7_5(const VlConfig& config, MWindow window,
                                          const ArbitraryStarts& starts,
                                          const checker::ExploreOptions& options);

} // namespace vlayer_mc
