#pragma once
// The search for a simulation relation over pairs of states. Seed 000 §3.1 (lines 350–354) asks
// of a simulation R ⊆ Q_X × Q_Y that, if x R y, every one-step move of X from x simulates an
// execution fragment of Y from y with the same trace, ending in related states. Checked here
// in a stronger, one-step form: from start pairs (x, y), each step x −a→ x′ of X must be
// matched by one step y −a→ y′ of Y with the same label (the same action name and
// parameters, internal actions too; a tick by a tick, one quantum each) and x′ R y′; every
// such (x′, y′) is a pair explored in turn. The pairs have their own store, parents and
// limits, so a step that cannot be matched is reported with the path of matched steps that
// led to it.
//
// Breadth-first: pairs get ids in the order they are found, each pair's steps of X in the
// generator's order, and for each the matching steps of Y in theirs. The first pair (by id)
// with a step that has no match is reported, and that step is the first of its steps that
// has none.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "checker/options.hpp"
#include "checker/state_store.hpp"
#include "checker/trace.hpp"
#include "tioa/successors.hpp"

namespace checker {

// The relation R: whether a state of X (x) and a state of Y (y) are related.
using PairRelation = std::function<bool(const Word* x, const Word* y)>;

struct StartPair {
  const Word* x; // a state of X
  const Word* y; // a state of Y
};

struct SimulationOptions {
  Limits limits; // states = pairs stored
  // The time limit counts from here, so that work before the search (finding the start
  // pairs, say) counts too.
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  // Memory held elsewhere while the search runs, which the memory limit counts as well.
  std::size_t memory_held = 0;
};

// A step of x that no step of y matches.
struct SimulationViolation {
  struct Candidate {
    tioa::StepLabel label; // y's step, with the same label as x's
    std::vector<Word> to;  // y′, not related to x′
  };

  StateId pair = 0;      // the pair (x, y) whose step of x is not matched
  std::size_t start = 0; // the start pair its path begins at (an index into the start list)
  tioa::StepLabel step;  // x's step
  std::vector<Word> to;  // x′
  // Every step of y with the same label, in the generator's order (none leads to a state
  // related to x′); empty when y has no such step.
  std::vector<Candidate> candidates;
  // From the start pair's x through the matched steps to the pair's x, then `step` to x′.
  Trace x_trace;
  // From the start pair's y through the steps that matched to the pair's y.
  Trace y_trace;
};

struct SimulationSearch {
  std::uint64_t pairs = 0;         // pairs stored
  std::uint64_t initial_pairs = 0; // distinct start pairs
  std::uint64_t edges = 0;         // (step of x, matching step of y) found
  std::uint32_t depth = 0;         // the most steps from a start pair to a stored pair
  double seconds = 0;              // since SimulationOptions::started, when the search ended
  // found: a step was not matched (`violation`); a limit: the pairs were not all expanded.
  StopReason stop = StopReason::finished;
  std::optional<SimulationViolation> violation;

  bool holds() const { return stop == StopReason::finished; }
};

// Explores the pairs reachable from `starts` (duplicates stored once) under the steps of `x`
// matched by those of `y` to pairs in `related`, until every pair is expanded, a step of x
// has no match, or a limit is hit (checked before each pair is expanded, in the order
// states, seconds, memory: the pair store and `memory_held`).
SimulationSearch search_simulation(const tioa::SuccessorGenerator& x,
                                   const tioa::SuccessorGenerator& y, const PairRelation& related,
                                   const std::vector<StartPair>& starts,
                                   const SimulationOptions& options = {});

} // namespace checker
