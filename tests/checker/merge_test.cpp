// The merge (checker/merge.hpp): candidates inserted worker by worker in frontier order,
// counts taken whole, the first target, and the limits.
#include <catch2/catch.hpp>

#include <vector>

#include "checker/merge.hpp"

using namespace checker;

namespace {

// One-word states: a state is its number. States 100 and 101 (ids 0, 1) are the level
// that was expanded.
struct Run {
  Exploration ex{1};
  std::vector<StateId> next;
  MemoryBudget budget;
  Insertion insertion;
  std::vector<Worker> workers{2, Worker(1)};

  explicit Run(std::uint64_t max_states = 0, std::uint64_t max_memory = 0)
      : budget(max_memory,
               [this] { return ex.memory_bytes() + next.capacity() * sizeof(StateId); }),
        insertion(ex, budget, max_states, true) {
    for (Word w : {100, 101}) {
      ex.store.insert(&w, hash_state(&w, 1));
      ex.parent.push_back(no_parent);
    }
  }
  // A candidate of worker t: `state`, reached from `from`.
  void candidate(std::size_t t, Word state, StateId from, bool target = false) {
    workers[t].states.push(&state);
    workers[t].candidates.push_back({hash_state(&state, 1), from, 1, target});
  }
  std::optional<StopReason> merge() { return merge_level(workers, ex, insertion, budget, next); }
};

} // namespace

TEST_CASE("merge: new states get ids in frontier order, duplicates are edges", "[checker][merge]") {
  Run run;
  run.candidate(0, 5, 0);
  run.candidate(0, 6, 0);
  run.candidate(1, 6, 1); // found by both workers: the first one's parent
  run.candidate(1, 7, 1);
  run.workers[1].edges.push_back({1, edge_to(0, 0)});
  run.workers[0].stuck.push_back(0);
  CHECK_FALSE(run.merge());
  CHECK(run.next == std::vector<StateId>{2, 3, 4});
  CHECK(run.ex.parent == std::vector<StateId>{no_parent, no_parent, 0, 0, 1});
  CHECK(*run.ex.store.state(3) == 6);
  CHECK(run.ex.stuck == std::vector<StateId>{0});
  // The workers' edges to known states first, then one per candidate.
  std::vector<std::pair<StateId, StateId>> edges;
  for (const Edge& e : run.ex.edge_list)
    edges.emplace_back(e.from, e.target());
  CHECK(edges == std::vector<std::pair<StateId, StateId>>{{1, 0}, {0, 2}, {0, 3}, {1, 3}, {1, 4}});
}

TEST_CASE("merge: the first target in frontier order stops it; the counts go in whole",
          "[checker][merge]") {
  Run run;
  run.workers[0].edge_count = 3;
  run.workers[0].expanded = 1;
  run.workers[1].edge_count = 4;
  run.workers[1].expanded = 1;
  run.workers[1].stuck.push_back(1);
  run.candidate(0, 5, 0);
  run.candidate(0, 6, 0, true);
  run.candidate(1, 7, 1, true);
  CHECK(run.merge() == StopReason::found);
  CHECK(run.ex.found == StateId{3});
  CHECK(run.ex.store.size() == 4);
  CHECK(run.ex.edges == 7);
  CHECK(run.ex.expanded == 2);
  CHECK(run.ex.stuck == std::vector<StateId>{1});
}

TEST_CASE("merge: state and memory limits", "[checker][merge][limits]") {
  SECTION("state limit") {
    Run run(3);
    run.candidate(0, 5, 0);
    run.candidate(1, 5, 1); // known: still fine
    run.candidate(1, 6, 1);
    CHECK(run.merge() == StopReason::state_limit);
    CHECK(run.ex.store.size() == 3);
    CHECK(run.ex.edge_list.size() == 2);
  }
  SECTION("memory limit") {
    Run run(0, 1);
    run.candidate(0, 5, 0);
    CHECK(run.merge() == StopReason::memory_limit);
    CHECK(run.ex.store.size() == 2);
  }
}
