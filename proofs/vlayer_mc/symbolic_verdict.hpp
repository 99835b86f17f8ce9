#pragma once
// A symbolic stabilisation run (symbolic_starts.hpp) judged as a property result, the same
// way for Lemma 7.3, Lemma 7.4 and Theorem 7.5. A worst time above the bound, and a start
// state that reaches a time-lock or endless zero-time steps, are explored again explicitly
// from the one start state the symbolic run picked: the trace is then check_stabilisation's,
// a real trace that replays, and its worst time must be the symbolic one (else a
// std::logic_error: the two ways disagree). "Holds" needs no time-lock and no endless
// zero-time steps. Coverage: every start state of the set, decided symbolically.

#include <cstdint>
#include <functional>
#include <string>

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "proofs/vlayer_mc/symbolic_starts.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

struct SymbolicClaim {
  std::string what;    // "Lemma 7.3 (in L1MC from any t > eps_sample on)"
  std::uint64_t bound; // quanta
  bool exact;          // a worst time above the bound is a counterexample (judge's `exact`)
  bool exhaustive;     // the legal set is all it should be (judge's `exhaustive`)
  std::string over;    // the start set, in words (coverage.over)
  // The explicit legal and settled sets (settled may be empty), for the run from a picked
  // start state.
  tioa::StatePredicate legal, settled;
  // Added to the message of a failure, from the explicit run's result (may be empty).
  std::function<std::string(const checker::PropertyResult&)> detail;
};

// `layer` is the automaton the run's space is of (its traces are that automaton's).
checker::PropertyResult judge_symbolic(const SymbolicRun& run, const tioa::Automaton& layer,
                                       const SymbolicClaim& claim,
                                       const checker::ExploreOptions& options);

// A number of states in three significant digits ("1.09e+16").
std::string scientific(double x);

} // namespace vlayer_mc
