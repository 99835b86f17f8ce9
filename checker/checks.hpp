#pragma once
// The checks, one algorithm per file. Each takes the system to check (its start set is
// part of it: use U(), Start() to choose), the property's predicates and the options,
// and returns a PropertyResult with verdict holds, violated or incomplete.

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "tioa/automaton.hpp"

namespace checker {

using tioa::Automaton;
using tioa::StatePredicate;

// Every reachable state satisfies `invariant`; else a shortest trace to one that does not.
PropertyResult check_invariant(const Automaton& system, const StatePredicate& invariant,
                               const ExploreOptions& options);

// L is a legal set (seed 000 §3.1): from every state of L (every valuation satisfying
// `legal`, reachable or not) every discrete step and every tick stays in L.
PropertyResult check_legal_set(const Automaton& system, const StatePredicate& legal,
                               const ExploreOptions& options);

// Def 3.5: every execution from a start state of `system` (typically U(A)||B) is in L
// from time t on. Measures the least such t (worst_time) with a witness, or gives a lasso
// (a cycle outside L in which time passes), or a deadlock / time-lock outside L.
PropertyResult check_stabilisation(const Automaton& system, const StatePredicate& legal,
                                   const ExploreOptions& options);
// The same, where the caller knows that from a `settled` state every execution is in L for
// good (e.g. L = the states reachable from a set, and `settled` that set): such states are
// counted in L and not expanded.
PropertyResult check_stabilisation(const Automaton& system, const StatePredicate& legal,
                                   const StatePredicate& settled, const ExploreOptions& options);

// Lemma 3.4 as a self-check: with S1 = executions of `system`, S1 -> L1 in t1 and
// Start(system, L1) -> L2 in t2, the direct measurement S1 -> L2 is at most t1 + t2.
PropertyResult check_transitivity(const Automaton& system, const StatePredicate& l1,
                                  const std::string& l1_name, const StatePredicate& l2,
                                  const std::string& l2_name, const ExploreOptions& options);

// No reachable state where nothing can happen: no action and (when timed) no tick. A stuck
// state where `ended` holds (the system has finished its work, e.g. every robot done) is a
// proper end, not a deadlock: counted in a note, never the verdict. Empty: none is.
PropertyResult check_no_deadlock(const Automaton& system, const ExploreOptions& options,
                                 const StatePredicate& ended = {},
                                 const std::string& ended_name = "");

// check_invariant and check_no_deadlock run on every store (ExploreOptions::store); on the
// fingerprint store a run that finds nothing is incomplete ("holds up to hash collisions").
// The other checks read the states or edges after the search (through StateReader, so on
// the exact and the compressed store) and throw this when asked for the fingerprint store,
// which keeps no states: std::invalid_argument naming `check`.
void require_stored_states(const ExploreOptions& options, const std::string& check);

} // namespace checker
