// The simulation-relation search (checker/simulation_relation.hpp) on counters whose pairs
// can be listed by hand: a relation that is a simulation (holds), a step that cannot be
// matched (violated, with the pair, the step and both traces), ticks matched by ticks only,
// and a state limit (incomplete).
#include <catch2/catch.hpp>

#include "checker/simulation_relation.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

// x in 0..top from 0; `inc` takes x to x + 1 below top. With `jump_to` >= 0, `jump` takes
// x = 2 to jump_to. With `reset_first`, an action `reset` (x > 0 to 0) is declared before
// `inc`, so that the same action has another index than in an automaton without it.
tioa::Automaton counter(const std::string& name, int top, int jump_to = -1,
                        bool reset_first = false) {
  tioa::Automaton c(name);
  const auto x = c.integer("x", 0, top, 0);
  if (reset_first)
    c.internal("reset")
        .pre([=](const State& s, const Params&) { return s[x] > 0; })
        .eff([=](State& s, const Params&) { s[x] = 0; });
  c.internal("inc")
      .pre([=](const State& s, const Params&) { return s[x] < top; })
      .eff([=](State& s, const Params&) { s[x] = s[x] + 1; });
  if (jump_to >= 0)
    c.internal("jump")
        .pre([=](const State& s, const Params&) { return s[x] == 2; })
        .eff([=](State& s, const Params&) { s[x] = jump_to; });
  return c;
}

// x in 0..top; each tick takes x one down (to 0 at the least). With `stuck_at_zero`, time
// cannot pass at x = 0, where an action `idle` is enabled instead.
tioa::Automaton clock_down(const std::string& name, int top, bool stuck_at_zero) {
  tioa::Automaton c(name);
  const auto x = c.integer("x", 0, top, top);
  if (stuck_at_zero)
    c.internal("idle").pre([=](const State& s, const Params&) { return s[x] == 0; });
  tioa::StatePredicate stop;
  if (stuck_at_zero)
    stop = [=](const State& s) { return s[x] == 0; };
  c.trajectories(
      [=](State& s) {
        if (s[x] > 0)
          s[x] = s[x] - 1;
      },
      stop);
  return c;
}

Words with_x(const tioa::Automaton& a, int value) {
  const tioa::Slot slot = slot_of(a, "x");
  return make_state(a, [&](State& s) { s.set<int>(slot, value); });
}

// x R y iff the two counters are equal.
PairRelation equal_x(const tioa::Automaton& a, const tioa::Automaton& b) {
  return [sa = slot_of(a, "x"), sb = slot_of(b, "x")](const Word* x, const Word* y) {
    return State(x, 0).code(sa) == State(y, 0).code(sb);
  };
}

std::vector<std::string> actions(const Trace& trace) {
  std::vector<std::string> out;
  for (std::size_t i = 1; i < trace.steps.size(); ++i)
    out.push_back(trace.steps[i].action);
  return out;
}

std::vector<std::int64_t> xs(const tioa::Automaton& a, const Trace& trace) {
  std::vector<std::int64_t> out;
  for (const auto& step : trace.steps)
    out.push_back(value_of(a, step.state, "x"));
  return out;
}

bool replays(const tioa::Automaton& a, const Trace& trace) {
  std::string why;
  const bool ok = replay(tioa::SuccessorGenerator(a), trace, &why);
  INFO(why);
  return ok;
}

} // namespace

// X counts to 2, Y to 3 and can also reset (declared first: `inc` is action 1 of Y, 0 of X).
// From (0, 0) every inc of x is matched by Y's inc: pairs (0,0), (1,1), (2,2).
TEST_CASE("simulation search: equal counters, a simulation", "[checker][simulation]") {
  const tioa::Automaton a = counter("X", 2);
  const tioa::Automaton b = counter("Y", 3, -1, /*reset_first=*/true);
  const tioa::SuccessorGenerator gx(a), gy(b);
  const Words x0 = with_x(a, 0), y0 = with_x(b, 0);
  // The same start pair twice is stored once.
  const SimulationSearch s =
      search_simulation(gx, gy, equal_x(a, b), {{x0.data(), y0.data()}, {x0.data(), y0.data()}});
  CHECK(s.holds());
  CHECK(s.stop == StopReason::finished);
  CHECK_FALSE(s.violation);
  CHECK(s.initial_pairs == 1);
  CHECK(s.pairs == 3);
  CHECK(s.edges == 2);
  CHECK(s.depth == 2);
}

// X jumps from 2 back to 0; Y has no jump, or one to 1. Two start pairs, (0,0) and (1,1):
// (2,2) is found from (1,1) (from (0,0), inc reaches the stored (1,1)), so its path starts at
// start pair 1 and takes one matched step.
TEST_CASE("simulation search: a step y cannot match", "[checker][simulation]") {
  const tioa::Automaton a = counter("X", 2, /*jump_to=*/0);
  const Words x0 = with_x(a, 0), x1 = with_x(a, 1);
  for (const int y_jump : {-1, 1}) {
    CAPTURE(y_jump);
    const tioa::Automaton b = counter("Y", 3, y_jump);
    const tioa::SuccessorGenerator gx(a), gy(b);
    const Words y0 = with_x(b, 0), y1 = with_x(b, 1);
    const SimulationSearch s =
        search_simulation(gx, gy, equal_x(a, b), {{x0.data(), y0.data()}, {x1.data(), y1.data()}});
    CHECK_FALSE(s.holds());
    CHECK(s.stop == StopReason::found);
    CHECK(s.initial_pairs == 2);
    CHECK(s.pairs == 3);
    CHECK(s.edges == 2); // (0,0) -inc-> (1,1) and (1,1) -inc-> (2,2)
    REQUIRE(s.violation);
    const SimulationViolation& v = *s.violation;
    CHECK(v.pair == 2);
    CHECK(v.start == 1);
    CHECK(gx.describe(v.step) == "jump");
    CHECK(value_of(a, v.to, "x") == 0);
    if (y_jump < 0) {
      CHECK(v.candidates.empty());
    } else {
      REQUIRE(v.candidates.size() == 1);
      CHECK(gy.describe(v.candidates[0].label) == "jump");
      CHECK(value_of(b, v.candidates[0].to, "x") == 1);
    }
    CHECK(actions(v.x_trace) == std::vector<std::string>{"inc", "jump"});
    CHECK(xs(a, v.x_trace) == std::vector<std::int64_t>{1, 2, 0});
    CHECK(actions(v.y_trace) == std::vector<std::string>{"inc"});
    CHECK(xs(b, v.y_trace) == std::vector<std::int64_t>{1, 2});
    CHECK(replays(a, v.x_trace));
    CHECK(replays(b, v.y_trace));
  }
}

// Ticks are matched by ticks, one quantum each: Y cannot let time pass at 0 (it has `idle`
// there, another label), X can.
TEST_CASE("simulation search: a tick is matched by a tick only", "[checker][simulation]") {
  const tioa::Automaton a = clock_down("X", 2, false);
  const tioa::SuccessorGenerator gx(a);
  const Words x2 = with_x(a, 2);

  const tioa::Automaton same = clock_down("Y", 2, false);
  const Words y2 = with_x(same, 2);
  const SimulationSearch holds = search_simulation(gx, tioa::SuccessorGenerator(same),
                                                   equal_x(a, same), {{x2.data(), y2.data()}});
  CHECK(holds.holds());
  CHECK(holds.pairs == 3); // (2,2), (1,1), (0,0)
  CHECK(holds.edges == 3); // the last tick from (0,0) to itself

  const tioa::Automaton stuck = clock_down("Y", 2, true);
  const tioa::SuccessorGenerator gy(stuck);
  const Words z2 = with_x(stuck, 2);
  const SimulationSearch s = search_simulation(gx, gy, equal_x(a, stuck), {{x2.data(), z2.data()}});
  REQUIRE(s.violation);
  CHECK(s.violation->step.is_tick());
  CHECK(s.violation->candidates.empty());
  CHECK(actions(s.violation->x_trace) == std::vector<std::string>{"tick", "tick", "tick"});
  CHECK(s.violation->x_trace.steps.back().time == 3);
  CHECK(s.violation->y_trace.steps.back().time == 2);
  CHECK(replays(a, s.violation->x_trace));
  CHECK(replays(stuck, s.violation->y_trace));
}

// A simulation whose pairs outnumber the limit: incomplete, no violation.
TEST_CASE("simulation search: a state limit gives incomplete", "[checker][simulation]") {
  const tioa::Automaton a = counter("X", 5);
  const tioa::Automaton b = counter("Y", 5);
  const tioa::SuccessorGenerator gx(a), gy(b);
  const Words x0 = with_x(a, 0), y0 = with_x(b, 0);
  SimulationOptions options;
  options.limits.max_states = 3;
  const SimulationSearch s =
      search_simulation(gx, gy, equal_x(a, b), {{x0.data(), y0.data()}}, options);
  CHECK_FALSE(s.holds());
  CHECK(s.stop == StopReason::state_limit);
  CHECK_FALSE(s.violation);
  CHECK(s.pairs == 3);
  CHECK(s.edges == 2);

  options.limits.max_states = 0; // no limit: the six pairs (i, i)
  CHECK(search_simulation(gx, gy, equal_x(a, b), {{x0.data(), y0.data()}}, options).pairs == 6);
}
