// R(A) (checker/reach.hpp) as a start-set operator beside Start and U
// (tests/tioa/operators_test.cpp).
#include <catch2/catch.hpp>

#include <set>

#include "checker/reach.hpp"
#include "tests/tioa/climb_fixture.hpp"
#include "tests/tioa/fail_fixture.hpp"

using namespace tioa;
using namespace tioa_test;
using Catch::Contains;

TEST_CASE("R(A): exactly the reachable states, and R(R(A)) is the same", "[checker][reach]") {
  const Climb climb;
  const Automaton r = checker::R(climb.a);
  const auto list = start_states(r);
  const std::set<Words> set(list.begin(), list.end());
  CHECK(list.size() == 4);
  CHECK(set == std::set<Words>{climb.state(0, false), climb.state(1, false), climb.state(2, false),
                               climb.state(2, true)});
  // x = 3 is in the domain but unreachable.
  CHECK(set.count(climb.state(3, false)) == 0);
  CHECK(set == reachable(climb.a).states);

  const Automaton rr = checker::R(r);
  CHECK(start_set(rr) == set);
  CHECK(start_states(rr).size() == 4);
  // R changes the start states only.
  CHECK(labels(steps(r, climb.state(0, false))) == std::vector<std::string>{"up"});

  // The same for a timed automaton with inputs and failures: R lists what a plain
  // breadth-first search reaches.
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  const std::set<Words> reached = reachable(f).states;
  CHECK(start_set(checker::R(f)) == reached);
  CHECK(start_set(checker::R(checker::R(f))) == reached);
  CHECK(reached.size() == 36);
}

TEST_CASE("R(A): an exploration cut short by a limit is a ModelError", "[checker][reach]") {
  const Climb climb;
  checker::ExploreOptions options;
  options.limits.max_states = 2;
  CHECK_THAT(model_error([&] { checker::R(climb.a, options); }),
             Contains("R(climb)") && Contains("could not all be explored"));
}
