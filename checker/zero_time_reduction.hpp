#pragma once
// Partial-order reduction of the steps that take no time (issue 14).
//
// In a timed model most states are in-between states of one instant: time cannot pass
// (the stop-when condition holds) until some instantaneous steps have been taken, and
// those steps (GPS updates, time updates, deliveries, ...) mostly touch different
// components, so a full search explores every interleaving of them. At such a state this
// explores only a stubborn set of steps (Valmari), built from what each step reads and
// writes (tioa/footprint.hpp):
//
//  - the tick is a step that depends on every other one; it is disabled here, so the set
//    holds every action that may write what the stop-when condition read in this state
//    (its necessary enabling set: until one of them runs, time still cannot pass);
//  - for the checked predicate (an invariant), every action that may write what the
//    predicate read in this state (until one of them runs, it keeps its value);
//  - for an action in the set with a step not enabled here, every action that may write
//    what its guard read here;
//  - for a step in the set that is enabled here, every action that may read what it
//    writes, or write what it reads or writes (here: what it read when its guard and
//    effect ran in this state).
//  - at least one enabled step that has a successor (a step with no choice has none).
// Reads are traced as the guards and effects run (tioa/state.hpp); writes are the
// footprints the model declares, or the whole component that owns the step. Every step
// run here is checked against its declared footprint: a read or write outside it is a
// ModelError.
//
// Why it is sound for what the checks using it ask (a state where the predicate fails, a
// state with no successor, a state where time cannot pass and nothing can happen):
//  * a path from this state that avoids the set changes nothing the stop-when
//    condition, the predicate or an enabled step of the set read, so along it time cannot
//    pass, the predicate keeps its value and that step stays enabled: every path to a
//    state the check looks for contains a step of the set;
//  * the first such step commutes with every step before it (none of them is in the set,
//    so none touches what it reads or writes): it can be moved to the front, and the
//    search, which takes it here, reaches the same state by a path one step shorter.
// By induction on the length of that path, every such state stays reachable. States where
// time can pass are always expanded in full. The reduced graph keeps every state the
// checks look for, but not every state or edge: counts, and traces, are those of the
// reduced graph (traces are real, not always the shortest).

#include <cstdint>
#include <optional>
#include <vector>

#include "tioa/action_footprints.hpp"
#include "tioa/successors.hpp"

namespace checker {

using tioa::Word;

class ZeroTimeReduction {
public:
  // `invariant`: the predicate whose failure the check looks for (empty: none).
  ZeroTimeReduction(const tioa::SuccessorGenerator& generator, tioa::StatePredicate invariant);

  // What one worker needs to expand a state; it keeps its memory from state to state.
  struct Scratch {
    std::vector<Word> successors; // the chosen successors, words() each
    std::vector<std::uint32_t> durations;
    std::vector<Word> traces; // per action: what its guards read (words() each)
    std::vector<Word> masks;  // one step's reads and writes, the predicate's and tick's reads
    struct Step {
      std::uint32_t action;
      tioa::Params params;
    };
    std::vector<Step> enabled;
    std::vector<std::uint32_t> first_enabled; // per action: its first step in `enabled`
    std::vector<std::uint8_t> disabled;       // per action: a step of its box is not enabled
    std::vector<std::uint8_t> chosen;         // per action: in the stubborn set
    std::vector<std::uint32_t> work;
    std::vector<Word> gathered;     // a bit set of actions
    std::uint32_t enabled_left = 0; // actions with an enabled step not in the set yet
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order; // (step, successor)
    std::vector<Word> sorted, state;
    std::uint64_t reduced = 0; // states where fewer steps than enabled were taken
  };

  // Fills scratch.successors and scratch.durations with the successors to explore from
  // `state`, in the order the generator gives them; nullopt when every successor is to be
  // explored because time can pass there (or one step at most is enabled): the caller then
  // runs the generator.
  std::optional<std::size_t> reduce(const Word* state, Scratch& scratch) const;

private:
  // ORs into `actions` (a bit set of actions) the row of `of_bit` of each bit of `mask`.
  void gather(const std::vector<Word>& of_bit, const Word* mask, Word* actions) const;
  // Puts in the set every action of the bit set `actions` not in it yet.
  void choose(const Word* actions, Scratch& s) const;
  // Puts in the set every action not in it that may write what `mask` holds.
  void add_writers(const Word* mask, Scratch& s) const;
  // Runs step `k` of scratch.enabled: appends its successors, checks its declared
  // footprint, and leaves what it read and wrote in `reads`, `writes`.
  void run_step(const Word* state, std::size_t k, Scratch& s, Word* reads, Word* writes) const;

  const tioa::SuccessorGenerator* generator_;
  tioa::StatePredicate invariant_;
  std::vector<tioa::ActionFootprint> footprints_; // per action, over its whole box
  std::uint32_t words_;
  std::uint32_t action_words_; // words of a bit set of actions
  // Per bit of the state, the bit set of the actions that may write it, and read it.
  std::vector<Word> writers_of_bit_, readers_of_bit_;
};

} // namespace checker
