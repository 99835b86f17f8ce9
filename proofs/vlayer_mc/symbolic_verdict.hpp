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
#include <optional>
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

// Counterexample first. A run from a part of the start set (`part`, in words) whose worst
// time exceeds the claim's bound, or that has none: the whole set's worst time is at least
// as late, so the verdict is the one the whole set would get (violated for an exact claim,
// not confirmed otherwise), from the part's witness. nullopt when the part is within the
// bound (or stopped): then only the whole set decides. The result's coverage is the part
// (`starts` sampled, chosen by that rule) of `all_states`; the part's worst time is a lower
// bound for the whole set, so it is given in the message and as a figure, not as the worst
// time.
std::optional<checker::PropertyResult>
judge_symbolic_part(const SymbolicRun& run, double all_states, const std::string& part,
                    const tioa::Automaton& layer, const SymbolicClaim& claim,
                    const checker::ExploreOptions& options);

// The result of judge_symbolic_part when the run from every start state that followed it
// (`whole`) stopped: said in a note.
checker::PropertyResult part_when_whole_stopped(checker::PropertyResult from_part,
                                                const SymbolicRun& whole);

// A number of states in three significant digits ("1.09e+16").
std::string scientific(double x);

} // namespace vlayer_mc
