// Traces (checker/trace.hpp): shortest paths from the explorer's parents, replay against
// the model, and the ways a tampered trace is caught.
#include <catch2/catch.hpp>

#include "checker/trace.hpp"
#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

std::string replay_error(const tioa::Automaton& a, const Trace& trace) {
  const tioa::SuccessorGenerator generator(a);
  std::string why;
  return replay(generator, trace, &why) ? "<replays>" : why;
}

// x in 0..2 from 0, next: x := (x + 1) mod 3.
tioa::Automaton cycle3() {
  tioa::Automaton a("cycle");
  const auto x = a.integer("x", 0, 2, 0);
  a.internal("next").eff([=](State& s, const Params&) { s[x] = (s[x] + 1) % 3; });
  return a;
}

} // namespace

TEST_CASE("trace_to: a shortest trace to every state, which replays", "[checker][trace]") {
  for (int n : {2, 3}) {
    const auto fischer = fischer::build(n, 1, 2);
    const auto& a = fischer.system;
    const tioa::SuccessorGenerator generator(a);
    const Exploration ex = explore(generator, a.start(), {});
    const auto depth = bfs_depths(a);
    REQUIRE(depth.size() == ex.store.size());
    std::uint32_t deepest = 0;
    for (StateId id = 0; id < ex.store.size(); ++id) {
      const Trace trace = trace_to(generator, ex, id);
      REQUIRE(trace.length() == depth.at(stored(ex, id)));
      REQUIRE(trace.steps.front().state == stored(ex, 0)); // the one start state
      REQUIRE(trace.steps.front().action.empty());
      REQUIRE(trace.steps.front().time == 0);
      REQUIRE(trace.steps.back().state == stored(ex, id));
      REQUIRE_FALSE(trace.loop_start);
      std::uint64_t ticks = 0;
      for (std::size_t i = 1; i < trace.steps.size(); ++i) {
        ticks += trace.steps[i].action == "tick" ? 1 : 0;
        REQUIRE(trace.steps[i].time == ticks); // time is quanta: ticks only
      }
      REQUIRE(replay_error(a, trace) == "<replays>");
      deepest = std::max<std::uint32_t>(deepest, static_cast<std::uint32_t>(trace.length()));
    }
    CHECK(deepest + 1 == ex.depth); // the last level expanded found nothing new
  }
}

TEST_CASE("trace_to: in an untimed model every step is one unit of time", "[checker][trace]") {
  const tioa::Automaton a = cycle3();
  const tioa::SuccessorGenerator generator(a);
  const Exploration ex = explore(generator, a.start(), {});
  const Trace trace = trace_to(generator, ex, 2);
  REQUIRE(trace.length() == 2);
  CHECK(trace.steps[1].action == "next");
  CHECK(trace.steps[1].time == 1);
  CHECK(trace.steps[2].time == 2);
  CHECK(value_of(a, trace.steps[2].state, "x") == 2);

  const Trace start = trace_to(generator, ex, 0);
  CHECK(start.length() == 0);
  CHECK(replay_error(a, start) == "<replays>");
}

TEST_CASE("extend: only along a step of the model", "[checker][trace]") {
  const tioa::Automaton a = cycle3();
  const tioa::SuccessorGenerator generator(a);
  auto x_is = [&](int v) {
    return make_state(a, [&](State& s) { s.set_code(a.layout().find("x")->slot(), v); });
  };
  Trace trace;
  trace.steps.push_back({"", 0, x_is(0)});
  CHECK(extend(generator, trace, x_is(1).data()));
  CHECK_FALSE(extend(generator, trace, x_is(1).data())); // 1 -> 1 is no step
  CHECK(extend(generator, trace, x_is(2).data()));
  CHECK(extend(generator, trace, x_is(0).data()));
  CHECK(trace.length() == 3);
  CHECK(trace.steps.back().time == 3);

  SECTION("a lasso that closes replays") {
    trace.loop_start = 0;
    CHECK(replay_error(a, trace) == "<replays>");
  }
  SECTION("a lasso that does not close is rejected") {
    trace.loop_start = 1; // x = 1 there, x = 0 at the end
    CHECK(replay_error(a, trace) ==
          "the lasso does not close: its last state differs from its loop start");
  }
  SECTION("a loop that starts at the last state is rejected") {
    trace.loop_start = 3;
    CHECK(replay_error(a, trace) == "the loop starts at or after the last state");
    trace.loop_start = 7;
    CHECK(replay_error(a, trace) == "the loop starts at or after the last state");
  }
}

TEST_CASE("replay: a tampered trace is rejected", "[checker][trace]") {
  // A shortest trace to a Fischer state with a process in CS: try, set, tick, tick, enter.
  const auto fischer = fischer::build(2, 1, 2);
  const auto& a = fischer.system;
  const tioa::SuccessorGenerator generator(a);
  const tioa::Slot first_location = slots_named(a, "loc").front();
  ExploreHooks hooks;
  hooks.target = [&](const Word* s) { return State(s, 0).code(first_location) == 3; }; // CS
  const Exploration ex = explore(generator, a.start(), {}, hooks);
  REQUIRE(ex.found);
  const Trace good = trace_to(generator, ex, *ex.found);
  REQUIRE(good.length() == 5);
  CHECK(good.steps[1].action == "try(1)");
  CHECK(good.steps[2].action == "set(1)");
  CHECK(good.steps[3].action == "tick");
  CHECK(good.steps[4].action == "tick");
  CHECK(good.steps[5].action == "enter(1)");
  CHECK(good.steps[5].time == 2);
  REQUIRE(replay_error(a, good) == "<replays>");

  Trace bad = good;
  SECTION("wrong action") {
    bad.steps[2].action = "set(2)";
    CHECK(replay_error(a, bad) ==
          "step 2 is labelled set(2) but no such step of the model leads there (it takes set(1))");
  }
  SECTION("wrong state") {
    bad.steps[3].state = bad.steps[1].state;
    CHECK(replay_error(a, bad) == "step 3 (tick) is not a transition");
  }
  SECTION("steps out of order") {
    std::swap(bad.steps[1], bad.steps[2]);
    CHECK(replay_error(a, bad) == "step 1 (set(1)) is not a transition");
  }
  SECTION("wrong time") {
    bad.steps[4].time = 1;
    CHECK(replay_error(a, bad) == "step 4 has the wrong time");
  }
  SECTION("a discrete step that claims time") {
    for (std::size_t i = 5; i < bad.steps.size(); ++i)
      ++bad.steps[i].time;
    CHECK(replay_error(a, bad) == "step 5 has the wrong time");
  }
  SECTION("a lasso that does not close") {
    bad.loop_start = 2;
    CHECK(replay_error(a, bad) ==
          "the lasso does not close: its last state differs from its loop start");
  }
  SECTION("empty") {
    bad.steps.clear();
    CHECK(replay_error(a, bad) == "empty trace");
  }
  SECTION("no reason asked for") {
    bad.steps[2].action = "set(2)";
    CHECK_FALSE(replay(generator, bad, nullptr));
  }
}

TEST_CASE("replay: any step of the model between two states is accepted", "[checker][trace]") {
  // Regression: `left` and `right` both take x from 0 to 1. The trace that takes `right`
  // is an execution of the model, but replay() once compared only the label of the first
  // step from 0 to 1 (`left`) and rejected it.
  tioa::Automaton a("two-ways");
  const auto x = a.integer("x", 0, 1, 0);
  a.internal("left").eff([=](State& s, const Params&) { s[x] = 1; });
  a.internal("right").eff([=](State& s, const Params&) { s[x] = 1; });
  Trace trace;
  trace.steps.push_back({"", 0, make_state(a, [](State&) {})});
  trace.steps.push_back({"right", 1, make_state(a, [&](State& s) { s[x] = 1; })});
  CHECK(replay_error(a, trace) == "<replays>");
}

TEST_CASE("render_state: variables and values in declaration order", "[checker][trace]") {
  enum class Light { red, green };
  tioa::Automaton a("render");
  const auto on = a.boolean("on", false);
  const auto n = a.integer("n", -2, 5, 0);
  const auto light = a.enumeration<Light>("light", {"RED", "GREEN"}, Light::red);
  const auto c = a.clock("c", 3, 0, true);
  const Words first = make_state(a, [&](State& s) {
    s[on] = false;
    s[n] = -2;
    s[light] = Light::red;
    s[c] = 0;
  });
  CHECK(render_state(a.layout(), first.data()) ==
        std::vector<std::pair<std::string, std::string>>{
            {"on", "false"}, {"n", "-2"}, {"light", "RED"}, {"c", "0"}});
  const Words second = make_state(a, [&](State& s) {
    s[on] = true;
    s[n] = 5;
    s[light] = Light::green;
    s.set_bottom(c);
  });
  CHECK(render_state(a.layout(), second.data()) ==
        std::vector<std::pair<std::string, std::string>>{
            {"on", "true"}, {"n", "5"}, {"light", "GREEN"}, {"c", "⊥"}});
}
