// Insertion of one state (checker/insertion.hpp): new states get the next id and their
// parent; the state and memory limits.
#include <catch2/catch.hpp>

#include <vector>

#include "checker/insertion.hpp"

using namespace checker;
using Outcome = Insertion::Outcome;

namespace {

// One-word states: a state is its number.
struct Run {
  Exploration ex{1};
  MemoryBudget budget;
  Insertion insertion;

  explicit Run(std::uint64_t max_states = 0, std::uint64_t max_memory = 0)
      : budget(max_memory, [this] { return ex.memory_bytes(); }),
        insertion(ex, budget, max_states) {}

  Insertion::Result insert(Word state, StateId parent) {
    return insertion.insert(&state, hash_state(&state, 1), parent);
  }
};

} // namespace

TEST_CASE("Insertion: a new state gets the next id and its parent", "[checker][insertion]") {
  Run run;
  const auto a = run.insert(7, no_parent);
  CHECK(a.outcome == Outcome::fresh);
  CHECK(a.id == 0);
  const auto b = run.insert(9, 0);
  CHECK(b.outcome == Outcome::fresh);
  CHECK(b.id == 1);
  const auto again = run.insert(7, 1);
  CHECK(again.outcome == Outcome::known);
  CHECK(again.id == 0);
  CHECK(run.ex.store.size() == 2);
  CHECK(run.ex.parent == std::vector<StateId>{no_parent, 0}); // the first parent stays
}

TEST_CASE("Insertion: at the state limit only known states get in", "[checker][insertion]") {
  Run run(2);
  CHECK(run.insert(1, no_parent).outcome == Outcome::fresh);
  CHECK(run.insert(2, no_parent).outcome == Outcome::fresh);
  CHECK(run.insert(2, 0).outcome == Outcome::known); // a space of exactly 2 states finishes
  CHECK(run.insert(3, 0).outcome == Outcome::state_limit);
  CHECK(run.ex.store.size() == 2);
}

TEST_CASE("Insertion: room for the state and its parent within the memory limit",
          "[checker][insertion]") {
  SECTION("the first state needs the store's first buffers") {
    Run free;
    free.insert(1, no_parent);
    REQUIRE(free.budget.peak() > 0);
    Run run(0, free.budget.peak() - 1);
    CHECK(run.insert(1, no_parent).outcome == Outcome::memory_limit);
    CHECK(run.ex.store.size() == 0);
    Run enough(0, free.budget.peak());
    CHECK(enough.insert(1, no_parent).outcome == Outcome::fresh);
  }
}
