#pragma once
// What the stabilisation checks of seed 000 §7.2 on VLayer[MC] share: Lemma 7.3
// (proofs/lemma_7_3.hpp), Lemma 7.4 (proofs/lemma_7_4.hpp) and Theorem 7.5
// (proofs/theorem_7_5.hpp).
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
// figure `covered` says which (proofs/vlayer_mc/arbitrary_starts.hpp).

#include <cstdint>
#include <string>

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/state_list.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// The states of `system`'s exploration that satisfy `keep`, as a list; `complete` becomes
// false when the exploration hit a limit, or the property's limits cut the list short (it is
// never set true).
StateList reached_where(const tioa::Automaton& system, const tioa::StatePredicate& keep,
                        const checker::ExploreOptions& options, bool& complete);

// A stabilisation measurement `m` judged against `bound` (quanta): holds (when
// `exhaustive`), incomplete or violated, with the figures `bound` and `measured`. `exact`
// says whether a time above the bound is a counterexample (false: only an upper bound was
// measured); `detail` is added to the message of a failure.
checker::PropertyResult judge(checker::PropertyResult m, std::uint64_t bound,
                              const std::string& what, bool exhaustive, bool exact,
                              const std::string& detail);

// The figure `known LMC`: how many classes the known part of LMC has, and from what.
std::string describe_known(const KnownLmc& known);

// "In LMC" as Lemma 7.4 and Theorem 7.5 measure it (lmc_measure_note): ResetMC or its
// targetless exception (D30), or a state of a known class (D29). `known` must outlive it.
tioa::StatePredicate in_measured_lmc(const VlConfig& config, const tioa::Automaton& layer,
                                     MWindow window, const KnownLmc& known);

// The notes and the trace system every stabilisation result of §7.2 carries: faults after
// t0, junk slots, the variant's repairs, the round length; its traces are `layer`'s (which
// has junk slots, D31).
checker::PropertyResult with_common_notes(checker::PropertyResult r, const VlConfig& config,
                                          const ArbitraryStarts& starts,
                                          const tioa::Automaton& layer);

// The note of the checks that measure the time into LMC (Lemma 7.4, Theorem 7.5).
extern const char* const lmc_measure_note;

} // namespace vlayer_mc
