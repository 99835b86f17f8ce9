#pragma once
// The relations of an automaton's steps and the sets of its predicates as BDDs, learned by
// running the automaton's own code (its guards, effects and trajectories are C++ lambdas, not
// formulas): a Shannon expansion over the state variables that the code reads. The code runs
// on a partial state whose unassigned variables hold code 0, with its reads traced
// (tioa::State's trace); when it read an unassigned variable, the state is split on that
// variable's codes and each part runs again; when it read only assigned ones, its outcome
// holds for every value of the others, and becomes one cube of the BDD. The unassigned
// variables that a step does not write keep their value (the frame); one that changed
// without a traced write is a ModelError, since the relation would be wrong.
//
// Exact for any code that reads the state only through tioa::State (which the footprint
// checks of the partial-order reduction ask of every model). Cross-checked against explicit
// exploration: the reachable states of VLayer[MC]'s environment on 1x1, 3,496,284 both ways
// (tests/checker/symbolic_test.cpp pins small automata).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "checker/symbolic_space.hpp"
#include "tioa/start_set.hpp"

namespace checker::symbolic {

// One group of steps (an action with all its parameters and choices, or the tick): the
// relation between the current bits and the next values of the bits it may write.
class StepRelation {
public:
  StepRelation(std::string name, const Space& space, std::vector<Word> writes, bdd relation);
  ~StepRelation();
  StepRelation(StepRelation&& other) noexcept;
  StepRelation(const StepRelation&) = delete;
  StepRelation& operator=(const StepRelation&) = delete;
  StepRelation& operator=(StepRelation&&) = delete;

  const std::string& name() const { return name_; }
  const bdd& relation() const { return relation_; }
  // The bits its steps may write (the others keep their value).
  const std::vector<Word>& writes() const { return writes_; }
  // The states one step of the group leads to from `set`, and those that lead into `set`.
  bdd image(const bdd& set) const;
  bdd preimage(const bdd& set) const;
  // The states where the group has a step.
  bdd enabled() const { return sources(relation_); }
  // For `steps`, a part of the relation: the states they start from, and those they lead to.
  bdd sources(const bdd& steps) const { return bdd_exist(steps, written_next_); }
  bdd targets(const bdd& steps) const {
    return bdd_replace(bdd_exist(steps, written_current_), to_current_);
  }

private:
  std::string name_;
  std::vector<Word> writes_;
  bdd relation_, written_current_, written_next_;
  bddPair* to_current_ = nullptr; // next bits of the written bits -> current
  bddPair* to_next_ = nullptr;    // and back
};

struct LearningFigures {
  std::uint64_t leaves = 0; // outcomes of the code run, one cube each
};

// Told now and then while a group is learned (every few thousand cubes): its name and the
// cubes learned for it so far. It may throw, to stop a learning that takes too long.
using LearningWatch = std::function<void(const std::string& group, std::uint64_t cubes)>;

// Every step of `action` (every parameter value of its box that its binders and filters
// admit, every choice); `writes`: what its footprint declares it may write
// (tioa/action_footprints.hpp).
StepRelation learn_action(const Space& space, std::size_t action, std::vector<Word> writes,
                          LearningFigures& figures, const LearningWatch& watch = {});
// One tick: the conjunction over the trajectory parts of "this part does not stop time, and
// evolves" (the parts write disjoint bits: each its own automaton's state).
StepRelation learn_tick(const Space& space, LearningFigures& figures,
                        const LearningWatch& watch = {});
// The states that satisfy `predicate` (valid codes only).
bdd learn_predicate(const Space& space, const tioa::StatePredicate& predicate,
                    LearningFigures& figures);
// The states of a start set (enumerated one by one: for small sets).
bdd start_states(const Space& space, const tioa::StartSet& start);

} // namespace checker::symbolic
