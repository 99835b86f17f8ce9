// Start insertion (checker/start_insertion.hpp): level 0 in enumeration order, in
// batches, canonicalised, with its target and limits.
#include <catch2/catch.hpp>

#include <vector>

#include "checker/start_insertion.hpp"

using namespace checker;

namespace {

// One-word states: the numbers listed, in order.
tioa::StartSet numbers(std::vector<Word> list) {
  return tioa::StartSet("numbers",
                        [list](Word* w, std::uint32_t, const tioa::StartSet::Visit& visit) {
                          for (Word x : list) {
                            w[0] = x;
                            visit();
                          }
                        });
}

std::vector<Word> range(Word n) {
  std::vector<Word> out;
  for (Word x = 0; x < n; ++x)
    out.push_back(x);
  return out;
}

struct StartRun {
  Exploration ex{1};
  MemoryBudget budget{0, [this] { return ex.memory_bytes(); }};
  Insertion insertion;
  std::vector<bool> batches; // after_batch(stopped), in order

  explicit StartRun(std::uint64_t max_states = 0) : insertion(ex, budget, max_states) {}

  template <class Hooks>
  std::optional<StopReason> insert(const tioa::StartSet& start, const Hooks& hooks,
                                   std::optional<StopReason> after = std::nullopt) {
    return insert_start_states(start, ex, hooks, insertion, [&](bool stopped) {
      batches.push_back(stopped);
      return after;
    });
  }
};

} // namespace

TEST_CASE("start insertion: level 0 in enumeration order, duplicates once",
          "[checker][start_insertion]") {
  StartRun run;
  CHECK_FALSE(run.insert(numbers({5, 3, 5, 8, 3}), hooks()));
  CHECK(run.ex.start_states == 3);
  CHECK(run.ex.store.size() == 3);
  CHECK(*run.ex.store.state(0) == 5);
  CHECK(*run.ex.store.state(1) == 3);
  CHECK(*run.ex.store.state(2) == 8);
  CHECK(run.ex.parent == std::vector<StateId>(3, no_parent));
  CHECK(run.batches == std::vector<bool>{false}); // one batch, then the (empty) rest
}

TEST_CASE("start insertion: batches of start_batch states, each followed by the checks",
          "[checker][start_insertion]") {
  StartRun run;
  CHECK_FALSE(run.insert(numbers(range(2 * start_batch + 1)), hooks()));
  CHECK(run.ex.start_states == 2 * start_batch + 1);
  CHECK(run.batches == std::vector<bool>{false, false, false});
  SECTION("the checks may stop the run, which ends the enumeration") {
    StartRun stopped;
    CHECK(stopped.insert(numbers(range(2 * start_batch + 1)), hooks(), StopReason::time_limit) ==
          StopReason::time_limit);
    CHECK(stopped.ex.start_states == start_batch);
    CHECK(stopped.batches == std::vector<bool>{false});
  }
}

TEST_CASE("start insertion: the canonical hook, the target and the state limit",
          "[checker][start_insertion]") {
  SECTION("canonical: one state per class, the first of each in order") {
    StartRun run;
    run.insert(numbers({4, 7, 2, 9}), hooks().with_canonical([](Word* w) { w[0] %= 2; }));
    CHECK(run.ex.start_states == 2);
    CHECK(*run.ex.store.state(0) == 0);
    CHECK(*run.ex.store.state(1) == 1);
  }
  SECTION("target: the first new start state where it holds") {
    StartRun run;
    const auto stop = run.insert(numbers({1, 3, 4, 6}),
                                 hooks().with_target([](const Word* w) { return *w % 2 == 0; }));
    CHECK(stop == StopReason::found);
    CHECK(run.ex.found == StateId{2});
    CHECK(run.ex.start_states == 3);
    CHECK(run.batches == std::vector<bool>{true}); // told the run has stopped
  }
  SECTION("state limit") {
    StartRun run(2);
    CHECK(run.insert(numbers({1, 2, 1, 3, 4}), hooks()) == StopReason::state_limit);
    CHECK(run.ex.start_states == 2);
  }
}
