// R(A) = Start(A, Reach_A) (checker/reach.hpp): A started in its reachable states.
#include <catch2/catch.hpp>

#include <set>

#include "checker/reach.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

TEST_CASE("R: the start states are the reachable states", "[checker][reach]") {
  const tioa::Automaton d = diamond();
  const tioa::Automaton r = R(d);
  std::set<Words> starts;
  Words buffer(r.words() + 1, 0);
  r.start().enumerate(buffer.data(), 0,
                      [&] { starts.insert(Words(buffer.begin(), buffer.begin() + r.words())); });
  std::set<Words> reachable;
  for (const auto& [state, depth] : bfs_depths(d))
    reachable.insert(state);
  CHECK(starts == reachable);
  CHECK(starts.size() == 4);

  // Exploring R(A) finds the same states, all at level 0.
  const tioa::SuccessorGenerator generator(r);
  const Exploration ex = explore(generator, r.start(), {});
  CHECK(ex.start_states == 4);
  CHECK(ex.store.size() == 4);
  CHECK(ex.edges == 4);
}

TEST_CASE("R: an exploration cut by a limit is a ModelError", "[checker][reach]") {
  ExploreOptions options;
  options.limits.max_states = 2;
  try {
    R(diamond(), options);
    FAIL("no ModelError");
  } catch (const tioa::ModelError& e) {
    CHECK(std::string(e.what()) == "R(diamond): the reachable states could not all be explored "
                                   "(state limit reached)");
  }
}
