// The checks (checker/checks.hpp, checker/property.hpp): for each, a case where the
// property holds and one where it fails, on automata whose answers are worked out by hand.
#include <catch2/catch.hpp>

#include <algorithm>

#include "checker/checks.hpp"
#include "checker/property.hpp"
#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

bool replays(const tioa::Automaton& a, const Trace& trace) {
  const tioa::SuccessorGenerator generator(a);
  std::string why;
  const bool ok = replay(generator, trace, &why);
  INFO(why);
  return ok;
}

StatePredicate variable_is(const tioa::Automaton& a, const std::string& name, int value) {
  const tioa::Slot slot = a.layout().find(name)->slot();
  const std::int64_t lo = a.layout().find(name)->lo;
  return [slot, lo, value](const State& s) {
    return lo + static_cast<std::int64_t>(s.code(slot)) == value;
  };
}

StatePredicate x_is_zero(const tioa::Automaton& a) {
  return variable_is(a, "x", 0);
}

// The token ring's predicates: at least one / exactly one process privileged.
StatePredicate some_privileged(const token_ring::TokenRing& ring) {
  return [privileges = ring.privileges](const State& s) { return privileges(s) >= 1; };
}
StatePredicate exactly_one_privileged(const token_ring::TokenRing& ring) {
  return [privileges = ring.privileges](const State& s) { return privileges(s) == 1; };
}

std::uint64_t duration(const Trace& t) {
  return t.steps.back().time - t.steps.front().time;
}

// The time of the last state of a witness before it enters L.
std::uint64_t last_time_outside(const Trace& t) {
  return t.steps[t.steps.size() - 2].time;
}

} // namespace

// ---------------------------------------------------------------------------- invariant

TEST_CASE("invariant: holds", "[checker][invariant]") {
  const tioa::Automaton d = diamond();
  const PropertyResult r = check_invariant(d, [](const State&) { return true; }, {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.kind == "invariant");
  CHECK(r.states == 4);
  CHECK(r.edges == 4);
  CHECK(r.time_unit == "steps");
  CHECK_FALSE(r.trace);
  CHECK(r.message == "all 4 reachable states satisfy it");
}

TEST_CASE("invariant: violated, with a shortest trace", "[checker][invariant]") {
  const tioa::Automaton d = diamond();
  const auto a = variable_is(d, "a", 1), b = variable_is(d, "b", 1);
  const PropertyResult r = check_invariant(d, [&](const State& s) { return !(a(s) && b(s)); }, {});
  CHECK(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_role == "counterexample");
  CHECK(r.trace_kind == "invariant");
  CHECK(r.trace->length() == 2);
  CHECK(r.trace->steps[1].action == "setA");
  CHECK(r.trace->steps[2].action == "setB");
  CHECK(replays(d, *r.trace));
  const State last(r.trace->steps.back().state.data(), 0);
  CHECK((a(last) && b(last)));
  CHECK(r.message == "a reachable state breaks the invariant; shortest trace: 2 steps");

  SECTION("a violating start state gives a trace of length 0") {
    const PropertyResult s = check_invariant(d, [&](const State& st) { return a(st); }, {});
    CHECK(s.verdict == Verdict::violated);
    REQUIRE(s.trace);
    CHECK(s.trace->length() == 0);
  }
}

TEST_CASE("invariant: a limit gives incomplete, never holds", "[checker][invariant][limits]") {
  const auto ring = token_ring::build(5, 4);
  ExploreOptions options;
  options.limits.max_states = 10;
  const PropertyResult r = check_invariant(
      ring.system, [](const State&) { return true; }, options);
  CHECK(r.verdict == Verdict::incomplete);
  CHECK(r.message.rfind("state limit reached after", 0) == 0);
  options.limits = {};
  options.limits.max_seconds = 1e-9;
  CHECK(check_invariant(
            ring.system, [](const State&) { return true; }, options)
            .verdict == Verdict::incomplete);
}

TEST_CASE("a property's later exploration on a spent state budget says so",
          "[checker][invariant][limits]") {
  // The runs of one property share --max-states (Limits::states_budget): the first spends
  // it, and the second stops before its first state with a message that says why.
  const auto ring = token_ring::build(5, 4);
  ExploreOptions options;
  options.limits.max_states = 10;
  options.limits.states_budget = std::make_shared<StatesBudget>();
  options.limits.states_budget->max = 10;
  const auto always = [](const State&) { return true; };
  const PropertyResult first = check_invariant(ring.system, always, options);
  options.limits.spend_states(first.states);
  CHECK(first.message.rfind("state limit reached after 10 states", 0) == 0);
  const PropertyResult second = check_invariant(ring.system, always, options);
  CHECK(second.verdict == Verdict::incomplete);
  CHECK(second.states == 0);
  CHECK(second.message.rfind("state limit reached before this exploration began: the "
                             "property's earlier explorations spent --max-states",
                             0) == 0);
}

// ----------------------------------------------------------------------------- deadlock

TEST_CASE("deadlock: holds when every reachable state can move", "[checker][deadlock]") {
  const auto ring = token_ring::build(4, 3);
  const PropertyResult r = check_no_deadlock(ring.system, {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.kind == "deadlock");
  CHECK(r.states == 81);
  CHECK(r.edges == 189);
  CHECK(r.message == "no deadlock in 81 reachable states");
}

TEST_CASE("deadlock: violated, with a trace to the first stuck state", "[checker][deadlock]") {
  const tioa::Automaton d = diamond();
  const PropertyResult r = check_no_deadlock(d, {});
  CHECK(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "deadlock");
  CHECK(r.trace->length() == 2);
  CHECK(replays(d, *r.trace));
  CHECK(r.message == "1 reachable states with no action (deadlock)");

  SECTION("a timed automaton where neither an action nor a tick can happen: time-lock") {
    tioa::Automaton a("lock");
    const auto c = a.clock("c", 2, 0);
    a.trajectories([=](State& s) { s.advance(c); }, [=](const State& s) { return s[c] == 2; });
    const PropertyResult t = check_no_deadlock(a, {});
    CHECK(t.verdict == Verdict::violated);
    CHECK(t.trace_kind == "time-lock");
    REQUIRE(t.trace);
    CHECK(t.trace->length() == 2);
    CHECK(t.trace->steps.back().time == 2);
    CHECK(replays(a, *t.trace));
  }
  SECTION("a limit gives incomplete") {
    ExploreOptions options;
    options.limits.max_memory_bytes = 1;
    const auto ring = token_ring::build(4, 3);
    CHECK(check_no_deadlock(ring.system, options).verdict == Verdict::incomplete);
  }
}

// ---------------------------------------------------------------------------- legal set

TEST_CASE("legal set: holds, closed under steps and ticks", "[checker][legal_set]") {
  SECTION("token ring N=4 K=3: exactly one privileged") {
    const auto ring = token_ring::build(4, 3);
    const PropertyResult r = check_legal_set(ring.system, exactly_one_privileged(ring), {});
    CHECK(r.verdict == Verdict::holds);
    CHECK(r.kind == "legal-set");
    CHECK(r.states == 21); // |L|, from tools/reference/peer_models.py
    CHECK(r.edges == 21);  // one privileged process: one step from each
  }
  SECTION("a timed countdown: x == 0 is closed under ticks") {
    const tioa::Automaton c = timed_countdown(3);
    const PropertyResult r = check_legal_set(c, x_is_zero(c), {});
    CHECK(r.verdict == Verdict::holds);
    CHECK(r.states == 1);
    CHECK(r.edges == 1); // the tick at x == 0 is a self-loop
    CHECK(r.time_unit == "quanta");
  }
}

TEST_CASE("legal set: closure is checked from every state of L, reachable or not",
          "[checker][legal_set]") {
  // x in 0..3 from 0: nothing moves from 0 or 1; escape takes x = 2 (never reached) to 3.
  tioa::Automaton a("escape");
  const auto x = a.integer("x", 0, 3, 0);
  a.internal("escape")
      .pre([=](const State& s, const Params&) { return s[x] == 2; })
      .eff([=](State& s, const Params&) { s[x] = 3; });
  const StatePredicate legal = [=](const State& s) { return s[x] <= 2; };

  // Reachability alone would not see it: L holds in every reachable state.
  REQUIRE(check_invariant(a, legal, {}).verdict == Verdict::holds);

  const PropertyResult r = check_legal_set(a, legal, {});
  CHECK(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_role == "counterexample");
  CHECK(r.trace_kind == "closure-step");
  REQUIRE(r.trace->length() == 1);
  CHECK(value_of(a, r.trace->steps[0].state, "x") == 2);
  CHECK(r.trace->steps[1].action == "escape");
  CHECK(value_of(a, r.trace->steps[1].state, "x") == 3);
  CHECK(replays(a, *r.trace));
  CHECK(r.message == "a step leaves the legal set from one of its states");

  SECTION("a tick can leave L too") {
    tioa::Automaton t("tick-escape");
    const auto c = t.clock("c", 3, 0);
    t.trajectories([=](State& s) { s.advance(c); });
    const PropertyResult u = check_legal_set(t, [=](const State& s) { return s[c] <= 1; }, {});
    CHECK(u.verdict == Verdict::violated);
    REQUIRE(u.trace);
    CHECK(value_of(t, u.trace->steps[0].state, "c") == 1);
    CHECK(u.trace->steps[1].action == "tick");
    CHECK(u.trace->steps[1].time == 1);
    CHECK(replays(t, *u.trace));
  }
  SECTION("an empty legal set is not a legal set") {
    const PropertyResult e = check_legal_set(a, [](const State&) { return false; }, {});
    CHECK(e.verdict == Verdict::violated);
    CHECK(e.states == 0);
    CHECK(e.message.find("empty") != std::string::npos);
  }
  SECTION("a state limit of |L| or more changes nothing") {
    ExploreOptions options;
    options.limits.max_states = 22;
    const auto ring = token_ring::build(4, 3); // |L| = 21
    CHECK(check_legal_set(ring.system, exactly_one_privileged(ring), options).verdict ==
          Verdict::holds);
  }
  SECTION("a state limit below |L| gives incomplete") {
    ExploreOptions options;
    options.limits.max_states = 2;
    const auto ring = token_ring::build(4, 3);
    const PropertyResult l = check_legal_set(ring.system, exactly_one_privileged(ring), options);
    CHECK(l.verdict == Verdict::incomplete);
    CHECK(l.message.rfind("state limit reached", 0) == 0);
  }
}

TEST_CASE("legal set: a state limit of exactly |L| is not hit", "[checker][legal_set][limits]") {
  // As in explore(), max_states means "at most this many": a run that covers exactly
  // max_states states finishes.
  const auto ring = token_ring::build(4, 3); // 81 states, |L| = 21
  ExploreOptions options;
  options.limits.max_states = 81;
  CHECK(check_invariant(ring.system, some_privileged(ring), options).verdict == Verdict::holds);
  options.limits.max_states = 21;
  const PropertyResult r = check_legal_set(ring.system, exactly_one_privileged(ring), options);
  INFO(r.message);
  CHECK(r.verdict == Verdict::holds);
  options.limits.max_states = 20;
  CHECK(check_legal_set(ring.system, exactly_one_privileged(ring), options).verdict ==
        Verdict::incomplete);
}

// ------------------------------------------------------------------------ stabilisation

TEST_CASE("stabilisation: an untimed countdown stabilises in exactly top steps",
          "[checker][stabilisation]") {
  for (bool jumps : {false, true}) {
    // With jumps (x -> x-2 as well) the shortest way is shorter; the worst stays top.
    const tioa::Automaton c = countdown(5, jumps);
    const PropertyResult r = check_stabilisation(c, x_is_zero(c), {});
    CHECK(r.verdict == Verdict::holds);
    CHECK(r.kind == "stabilisation");
    CHECK(r.time_unit == "steps");
    CHECK(r.worst_time == 5u);
    CHECK(r.last_time_outside == 4u);
    REQUIRE(r.trace);
    CHECK(r.trace_role == "witness");
    CHECK(r.trace_kind == "worst-case");
    CHECK(r.trace->length() == 5);
    CHECK(r.trace->steps.back().time == 5);
    CHECK(last_time_outside(*r.trace) == 4);
    CHECK(value_of(c, r.trace->steps.front().state, "x") == 5);
    CHECK(value_of(c, r.trace->steps.back().state, "x") == 0);
    CHECK(replays(c, *r.trace));
    // x == 0 has nothing to do: a deadlock, but inside L, so only a note.
    REQUIRE(r.notes.size() == 1);
    CHECK(r.notes[0].rfind("1 reachable states in L from which", 0) == 0);
    CHECK(r.message == "every execution is in L from time 5 steps on (an execution can still be "
                       "outside L at time 4)");
  }
}

TEST_CASE("stabilisation: a timed countdown stabilises in exactly top quanta",
          "[checker][stabilisation]") {
  const tioa::Automaton c = timed_countdown(4);
  const PropertyResult r = check_stabilisation(c, x_is_zero(c), {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.time_unit == "quanta");
  CHECK(r.worst_time == 4u);
  CHECK(r.last_time_outside == 3u);
  REQUIRE(r.trace);
  CHECK(r.trace->length() == 4);
  CHECK(duration(*r.trace) == 4);
  CHECK(last_time_outside(*r.trace) == 3);
  CHECK(value_of(c, r.trace->steps.back().state, "x") == 0);
  CHECK(replays(c, *r.trace));
  CHECK(r.notes.empty());
}

// The graph analysis after the exploration counts against the memory limit too: with a
// limit the exploration fits in but the graph does not, the verdict is incomplete.
TEST_CASE("stabilisation: a graph over the memory limit gives incomplete",
          "[checker][stabilisation][limits]") {
  // (Five processes: with fewer the graph is smaller than the level's buffers.)
  const auto fischer = fischer::build(5, 1, 2);
  const tioa::SuccessorGenerator generator(fischer.system);
  ExploreHooks hooks;
  hooks.record_edges = true;
  const Exploration ex = explore(generator, fischer.system.start(), {}, hooks);
  REQUIRE(ex.complete());
  // The store, parents and edges (the graph takes them over, they are not copied), then
  // legal and settled, and the components' of, index, low and on_stack.
  const std::size_t n = ex.store.size();
  REQUIRE(ex.edge_offsets.size() == n + 1); // every state expanded
  const std::size_t graph = 2 * n + 13 * n;
  ExploreOptions options;
  REQUIRE(ex.peak_memory_bytes < ex.memory_bytes() + graph); // the exploration fits
  options.limits.max_memory_bytes = ex.memory_bytes() + graph - 1;
  const tioa::StatePredicate legal = fischer.at_most_one_in_cs;
  const PropertyResult r = check_stabilisation(fischer.system, legal, options);
  CHECK(r.verdict == Verdict::incomplete);
  CHECK(r.states == n);
  CHECK(r.message.find("memory limit reached after the exploration") == 0);
  CHECK_FALSE(r.trace);
  options.limits.max_memory_bytes = 0;
  CHECK(check_stabilisation(fischer.system, legal, options).verdict != Verdict::incomplete);
}

// Settled states (the caller vouches that executions are in L for good from them) are not
// expanded and count as letting time pass: with x <= 2 settled, the timed countdown from 4
// is in L from time 2 on, and no time-lock or deadlock note is given for them.
TEST_CASE("stabilisation: settled states end the measurement", "[checker][stabilisation]") {
  const tioa::Automaton c = timed_countdown(4);
  const tioa::StatePredicate settled = [&](const tioa::State& s) {
    return s.get<int>(tioa::find_variable<int>(c, "x")) <= 2;
  };
  const PropertyResult r = check_stabilisation(c, x_is_zero(c), settled, {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.worst_time == 2u);
  CHECK(r.notes.empty());
  REQUIRE(r.trace);
  CHECK(value_of(c, r.trace->steps.back().state, "x") == 2);
  CHECK(replays(c, *r.trace));
}

TEST_CASE("stabilisation: zero-time cycles outside L give a note, not a violation",
          "[checker][stabilisation]") {
  // As the timed countdown, with a flag that flips in zero time while x > 0: each x > 0
  // is a zero-time cycle of two states; time still brings every execution to x == 0.
  const tioa::Automaton c = timed_countdown(4, true);
  const PropertyResult r = check_stabilisation(c, x_is_zero(c), {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.worst_time == 4u);
  REQUIRE(r.trace);
  CHECK(duration(*r.trace) == 4);
  CHECK(replays(c, *r.trace));
  REQUIRE(r.notes.size() == 1);
  CHECK(r.notes[0].rfind("4 zero-time cycles outside L", 0) == 0);
}

TEST_CASE("stabilisation: every start state in L", "[checker][stabilisation]") {
  const tioa::Automaton d = diamond();
  const PropertyResult r = check_stabilisation(d, [](const State&) { return true; }, {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.worst_time == 0u);
  CHECK_FALSE(r.trace);
  CHECK(r.message == "every execution is in L from its start on");
}

TEST_CASE("stabilisation: L need not be closed; time counts to the last state outside L",
          "[checker][stabilisation]") {
  // x in 0..3 from anywhere, dec: x := x - 1 while x > 0. L = {0, 2}: from 3 an execution
  // enters L at 2, leaves it for 1, and is in L for good at 0, after 3 steps.
  const tioa::Automaton c = countdown(3);
  const auto x = tioa::Variable<int>{slot_of(c, "x")};
  const StatePredicate legal = [=](const State& s) { return s[x] % 2 == 0; };
  const PropertyResult r = check_stabilisation(c, legal, {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.worst_time == 3u);
  CHECK(r.last_time_outside == 2u);
  REQUIRE(r.trace);
  CHECK(r.trace->length() == 3);
  CHECK(last_time_outside(*r.trace) == 2);
  CHECK(value_of(c, r.trace->steps.front().state, "x") == 3);
  CHECK(replays(c, *r.trace));
  const bool noted = std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
    return n.rfind("L is not closed: 1 reachable steps leave it", 0) == 0;
  });
  CHECK(noted);
  // The legal-set check is where closure fails.
  CHECK(check_legal_set(c, legal, {}).verdict == Verdict::violated);
}

TEST_CASE("stabilisation: leaving L again and again for ever is a lasso",
          "[checker][stabilisation]") {
  // x in 0..1 from 0 (in L): flip goes 0 -> 1 -> 0 for ever; 1 is outside L.
  tioa::Automaton a("blink");
  const auto x = a.integer("x", 0, 1, 0);
  a.internal("flip").eff([=](State& s, const Params&) { s[x] = 1 - s[x]; });
  const PropertyResult r = check_stabilisation(a, x_is_zero(a), {});
  CHECK(r.verdict == Verdict::violated);
  CHECK(r.trace_kind == "lasso");
  REQUIRE(r.trace);
  REQUIRE(r.trace->loop_start);
  CHECK(r.trace->length() - *r.trace->loop_start == 2);
  CHECK(replays(a, *r.trace));
}

TEST_CASE("stabilisation: a cycle outside L is a lasso", "[checker][stabilisation]") {
  // x in 0..4 from 4: 4 -> 1, then 1 -> 2 -> 3 -> 1 for ever; 3 may also go to 0 (L).
  tioa::Automaton a("loop");
  const auto x = a.integer("x", 0, 4, 4);
  a.internal("enter")
      .pre([=](const State& s, const Params&) { return s[x] == 4; })
      .eff([=](State& s, const Params&) { s[x] = 1; });
  a.internal("next")
      .pre([=](const State& s, const Params&) { return s[x] >= 1 && s[x] <= 3; })
      .eff([=](State& s, const Params&) { s[x] = s[x] % 3 + 1; });
  a.internal("leave")
      .pre([=](const State& s, const Params&) { return s[x] == 3; })
      .eff([=](State& s, const Params&) { s[x] = 0; });
  const PropertyResult r = check_stabilisation(a, x_is_zero(a), {});
  CHECK(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_role == "counterexample");
  CHECK(r.trace_kind == "lasso");
  REQUIRE(r.trace->loop_start);
  CHECK(*r.trace->loop_start == 1); // stem 4 -> 1
  CHECK(r.trace->length() == 4);    // cycle 1 -> 2 -> 3 -> 1
  CHECK(value_of(a, r.trace->steps[1].state, "x") == 1);
  CHECK(r.trace->steps.back().state == r.trace->steps[1].state);
  for (const auto& step : r.trace->steps)
    CHECK(value_of(a, step.state, "x") != 0);
  CHECK(replays(a, *r.trace));
  CHECK(r.message.find("(lasso: stem 1, cycle 3 steps)") != std::string::npos);
}

TEST_CASE("stabilisation: ticking for ever outside L is a lasso", "[checker][stabilisation]") {
  // done from false; time passes freely and changes nothing; finish sets done.
  tioa::Automaton a("idle");
  const auto done = a.boolean("done", false);
  a.internal("finish").eff([=](State& s, const Params&) { s[done] = true; });
  a.trajectories({});
  const PropertyResult r = check_stabilisation(a, [=](const State& s) { return s[done]; }, {});
  CHECK(r.verdict == Verdict::violated);
  CHECK(r.trace_kind == "lasso");
  REQUIRE(r.trace);
  REQUIRE(r.trace->loop_start);
  CHECK(*r.trace->loop_start == 0);
  CHECK(r.trace->length() == 1);
  CHECK(r.trace->steps[1].action == "tick");
  CHECK(duration(*r.trace) == 1);
  CHECK(replays(a, *r.trace));
}

TEST_CASE("stabilisation: the lasso's cycle lets time pass", "[checker][stabilisation]") {
  // Regression: outside L, `wait` and a tick both lead from the state to itself; only the
  // tick lets time pass. The trace was once rebuilt with the first step reaching the
  // state, `wait`, which printed a Zeno cycle as the counterexample.
  tioa::Automaton a("wait");
  const auto done = a.boolean("done", false);
  a.internal("wait");
  a.internal("finish").eff([=](State& s, const Params&) { s[done] = true; });
  a.trajectories({});
  const PropertyResult r = check_stabilisation(a, [=](const State& s) { return s[done]; }, {});
  CHECK(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  REQUIRE(r.trace->loop_start);
  CHECK(replays(a, *r.trace));
  const auto loop_time = r.trace->steps.back().time - r.trace->steps[*r.trace->loop_start].time;
  CHECK(loop_time > 0);
}

TEST_CASE("stabilisation: the witness is still outside L at last_time_outside",
          "[checker][stabilisation]") {
  // Regression: the timed countdown with `skip`, a zero-time action that does what a tick
  // does. The worst case goes by ticks (outside L until time 3, in L from 4); the witness
  // was once rebuilt with `skip` steps and reached L at time 0.
  tioa::Automaton c("skip-countdown");
  const auto x = c.integer("x", 0, 4, std::nullopt);
  c.internal("skip")
      .pre([=](const State& s, const Params&) { return s[x] > 0; })
      .eff([=](State& s, const Params&) { s[x] = s[x] - 1; });
  c.trajectories([=](State& s) {
    if (s[x] > 0)
      s[x] = s[x] - 1;
  });
  const tioa::Automaton u = tioa::U(c);
  const PropertyResult r = check_stabilisation(u, x_is_zero(u), {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.worst_time == 4u);
  CHECK(r.last_time_outside == 3u);
  REQUIRE(r.trace);
  CHECK(replays(u, *r.trace));
  REQUIRE(r.trace->length() == 4);
  CHECK(last_time_outside(*r.trace) == 3);
}

TEST_CASE("stabilisation: a zero-time trap outside L is a time-lock", "[checker][stabilisation]") {
  // Regression: time never passes (stop-when always) and `flip` toggles b for ever;
  // nothing sets done, so no execution ever reaches L = done, and none is stuck. The
  // checker once answered holds with a witness that never reached L. Time can never pass
  // again outside L: a time-lock.
  tioa::Automaton a("zeno-trap");
  const auto b = a.boolean("b", false);
  const auto done = a.boolean("done", false);
  a.internal("flip").eff([=](State& s, const Params&) { s[b] = !s[b]; });
  a.trajectories({}, [](const State&) { return true; });
  const StatePredicate legal = [=](const State& s) { return s[done]; };
  const PropertyResult r = check_stabilisation(a, legal, {});
  INFO(r.message);
  CHECK(r.verdict == Verdict::violated);
  CHECK(r.trace_kind == "time-lock");
  REQUIRE(r.trace);
  CHECK(r.trace->length() == 0); // the start state already is such a state
}

TEST_CASE("stabilisation: stuck outside L is a violation", "[checker][stabilisation]") {
  SECTION("a deadlock") {
    // x in 0..2 from anywhere: only 2 moves (to 1); 1 is stuck outside L = {0}.
    tioa::Automaton a("stuck");
    const auto x = a.integer("x", 0, 2, std::nullopt);
    a.internal("dec")
        .pre([=](const State& s, const Params&) { return s[x] == 2; })
        .eff([=](State& s, const Params&) { s[x] = 1; });
    const tioa::Automaton u = tioa::U(a);
    const PropertyResult r = check_stabilisation(u, x_is_zero(u), {});
    CHECK(r.verdict == Verdict::violated);
    CHECK(r.trace_kind == "deadlock");
    REQUIRE(r.trace);
    CHECK(value_of(u, r.trace->steps.back().state, "x") == 1);
    CHECK(r.trace->length() == 0); // 1 is itself a start state
    CHECK(replays(u, *r.trace));
    CHECK(r.message == "an execution gets stuck outside L (deadlock: no action)");
  }
  SECTION("a deadlock inside L is only noted") {
    const tioa::Automaton c = countdown(3); // 0 is stuck, but in L
    const PropertyResult r = check_stabilisation(c, x_is_zero(c), {});
    CHECK(r.verdict == Verdict::holds);
    REQUIRE(r.notes.size() == 1);
    CHECK(r.notes[0] == "1 reachable states in L from which no step is possible (deadlock)");
  }
  SECTION("a time-lock") {
    // A clock c from 0 (cap 2) that stops time at 2, with nothing to do there; L: never.
    tioa::Automaton a("lock");
    const auto c = a.clock("c", 2, 0);
    const auto done = a.boolean("done", false);
    a.trajectories([=](State& s) { s.advance(c); }, [=](const State& s) { return s[c] == 2; });
    const PropertyResult r = check_stabilisation(a, [=](const State& s) { return s[done]; }, {});
    CHECK(r.verdict == Verdict::violated);
    CHECK(r.trace_kind == "time-lock");
    REQUIRE(r.trace);
    CHECK(r.trace->length() == 2);
    CHECK(duration(*r.trace) == 2);
    CHECK(replays(a, *r.trace));
    CHECK(r.message == "an execution reaches a state outside L from which time can never pass "
                       "again (time-lock)");
  }
}

TEST_CASE("stabilisation: a limit gives incomplete", "[checker][stabilisation][limits]") {
  const auto ring = token_ring::build(5, 4);
  ExploreOptions options;
  options.limits.max_states = 100;
  const PropertyResult r = check_stabilisation(ring.system, exactly_one_privileged(ring), options);
  CHECK(r.verdict == Verdict::incomplete);
  CHECK_FALSE(r.worst_time);
}

// ------------------------------------------------------------------------- transitivity

TEST_CASE("transitivity: holds, with t1, t2 and the direct time", "[checker][transitivity]") {
  // Countdown from 6: L1 = x <= 2 after 4 steps, L2 = x == 0 two steps later.
  const tioa::Automaton c = countdown(6);
  const auto x = tioa::Variable<int>{c.layout().find("x")->slot()};
  const PropertyResult r = check_transitivity(
      c, [=](const State& s) { return s[x] <= 2; }, "x<=2",
      [=](const State& s) { return s[x] == 0; }, "x==0", {});
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.kind == "transitivity");
  CHECK(r.worst_time == 6u);
  CHECK(r.figures == std::vector<std::pair<std::string, std::string>>{{"t1 (start -> x<=2)", "4"},
                                                                      {"t2 (x<=2 -> x==0)", "2"},
                                                                      {"t (start -> x==0)", "6"}});
  CHECK(r.message == "start -> x==0 in 6 <= t1 + t2 = 4 + 2 steps");
}

TEST_CASE("transitivity: a failing stage is the verdict", "[checker][transitivity]") {
  // x in 0..3 from anywhere: 3 <-> 2 for ever, 1 -> 0. L1 = x <= 1 is never reached from
  // 2 or 3, so the first premise fails; the lemma then says nothing, and the composed claim
  // is violated with the stage's counterexample (a vacuous "holds" before issue 17).
  tioa::Automaton a("split");
  const auto x = a.integer("x", 0, 3, std::nullopt);
  a.internal("swap")
      .pre([=](const State& s, const Params&) { return s[x] >= 2; })
      .eff([=](State& s, const Params&) { s[x] = 5 - s[x]; });
  a.internal("dec")
      .pre([=](const State& s, const Params&) { return s[x] == 1; })
      .eff([=](State& s, const Params&) { s[x] = 0; });
  const tioa::Automaton u = tioa::U(a);
  const PropertyResult r = check_transitivity(
      u, [=](const State& s) { return s[x] <= 1; }, "x<=1",
      [=](const State& s) { return s[x] == 0; }, "x==0", {});
  CHECK(r.verdict == Verdict::violated);
  CHECK(r.message.rfind("a stage fails, so Lemma 3.4 cannot compose them: start -> x<=1: ", 0) ==
        0);
  REQUIRE(r.trace);
  CHECK(r.trace->loop_start); // the lasso that never reaches x <= 1
  CHECK(r.figures ==
        std::vector<std::pair<std::string, std::string>>{{"t1 (start -> x<=1)", "violated"},
                                                         {"t2 (x<=1 -> x==0)", "1"},
                                                         {"t (start -> x==0)", "violated"}});

  SECTION("the second premise") {
    // L1 = anything: t1 = 0, but from L1 = every state, x == 0 is not always reached.
    const PropertyResult s = check_transitivity(
        u, [](const State&) { return true; }, "true", [=](const State& st) { return st[x] == 0; },
        "x==0", {});
    CHECK(s.verdict == Verdict::violated);
    CHECK(s.message.rfind("a stage fails, so Lemma 3.4 cannot compose them: true -> x==0: ", 0) ==
          0);
  }
  SECTION("a limit gives incomplete") {
    ExploreOptions options;
    options.limits.max_states = 1;
    const PropertyResult l = check_transitivity(
        u, [=](const State& s) { return s[x] <= 1; }, "x<=1",
        [=](const State& s) { return s[x] == 0; }, "x==0", options);
    CHECK(l.verdict == Verdict::incomplete);
  }
}

// ----------------------------------------------------------------------------- property

TEST_CASE("run_property: dispatches on the kind and names the result", "[checker][property]") {
  const auto ring = token_ring::build(4, 3);
  const std::vector<Property> properties{
      {"some-privileged",
       "at least one",
       PropertyKind::invariant,
       some_privileged(ring),
       "",
       {},
       ""},
      {"legal-closure",
       "L is closed",
       PropertyKind::legal_set,
       exactly_one_privileged(ring),
       "",
       {},
       ""},
      {"convergence",
       "U(A) reaches L",
       PropertyKind::stabilisation,
       exactly_one_privileged(ring),
       "",
       {},
       ""},
      {"transitivity", "Lemma 3.4", PropertyKind::transitivity, exactly_one_privileged(ring), "",
       [privileges = ring.privileges](const State& s) { return privileges(s) <= 2; }, ""}};
  const std::vector<std::string> kinds{"invariant", "legal-set", "stabilisation", "transitivity"};
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const Property& p = properties[i];
    CHECK(to_string(p.kind) == kinds[i]);
    const PropertyResult r = run_property(ring.system, p, {});
    CHECK(r.name == p.name);
    CHECK(r.description == p.description);
    CHECK(r.kind == kinds[i]);
    CHECK(r.verdict == Verdict::holds);
  }
  Property deadlock{"no-deadlock", "no deadlock", PropertyKind::deadlock, {}, "", {}, ""};
  const PropertyResult r = run_property(diamond(), deadlock, {});
  CHECK(to_string(PropertyKind::deadlock) == std::string("deadlock"));
  CHECK(r.name == "no-deadlock");
  CHECK(r.kind == "deadlock");
  CHECK(r.verdict == Verdict::violated);
  CHECK(to_string(Verdict::holds) == std::string("holds"));
  CHECK(to_string(Verdict::violated) == std::string("violated"));
  CHECK(to_string(Verdict::incomplete) == std::string("incomplete"));
}

// Issue 15: a verdict claims only what was covered.
TEST_CASE("run_property: holds only on all the start states a statement quantifies over",
          "[checker][property][coverage]") {
  const auto ring = token_ring::build(4, 3);
  Property invariant{
      "some-privileged", "", PropertyKind::invariant, some_privileged(ring), "", {}, ""};
  const PropertyResult all = run_property(ring.system, invariant, {});
  CHECK(all.verdict == Verdict::holds);
  CHECK(all.coverage.starts == Starts::all);
  CHECK(all.coverage.count == all.coverage.of);
  CHECK(all.coverage.count >= 1);

  // A custom check that covered a part of its statement: its holds is incomplete.
  const auto covering = [](Starts starts) {
    return Property{
        "part", "", PropertyKind::custom, {}, "", {}, "", [starts](const ExploreOptions&) {
          PropertyResult r;
          r.verdict = Verdict::holds;
          r.message = "no step leaves L";
          r.coverage = {starts, 7, 100, "L", "drawn at random"};
          return r;
        }};
  };
  const PropertyResult sampled = run_property(ring.system, covering(Starts::sampled), {});
  CHECK(sampled.verdict == Verdict::incomplete);
  CHECK(sampled.message ==
        "holds on 7 of 100 (drawn at random), not on all of L: no step leaves L");
  const PropertyResult one = run_property(ring.system, covering(Starts::one), {});
  CHECK(one.verdict == Verdict::incomplete);
  CHECK_THAT(one.message, Catch::StartsWith("holds from one start state"));
  CHECK(run_property(ring.system, covering(Starts::all), {}).verdict == Verdict::holds);
  CHECK(describe(sampled.coverage) == "sampled, 7 of 100: L (drawn at random)");

  // A violation found on a part is a violation.
  Property broken = covering(Starts::sampled);
  broken.run = [](const ExploreOptions&) {
    PropertyResult r;
    r.verdict = Verdict::violated;
    r.coverage.starts = Starts::sampled;
    return r;
  };
  CHECK(run_property(ring.system, broken, {}).verdict == Verdict::violated);
}

// Issue 17: --max-seconds is a budget for the whole property. A property made of several
// explorations stops them all at one deadline: once it has passed, the next exploration
// stops at its first check instead of spending max_seconds of its own.
TEST_CASE("run_property: the time limit is one deadline for all of a property's explorations",
          "[checker][property][limits]") {
  const auto big = fischer::build(8, 1, 2);
  std::vector<PropertyResult> parts;
  const Property two_searches{
      "two", "", PropertyKind::custom, {}, "", {}, "", [&](const ExploreOptions& o) {
        for (int i = 0; i < 2; ++i)
          parts.push_back(check_no_deadlock(big.system, o));
        return parts.back();
      }};
  ExploreOptions options;
  options.limits.max_seconds = 0.05;
  const PropertyResult r = run_property(big.system, two_searches, options);
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].verdict == Verdict::incomplete);
  CHECK_THAT(parts[0].message, Catch::StartsWith("time limit reached"));
  CHECK(r.verdict == Verdict::incomplete);
  // The second search met the deadline at its first check: far fewer states than the first.
  CHECK(parts[1].states * 4 < parts[0].states);
}

TEST_CASE("a check notes an input the system leaves open over a large box", "[checker]") {
  // 200 x 200 points of `go` in every state: noted; 50 x 50 is below the threshold, and a
  // system whose component outputs the input has none left.
  const auto receiver = [](int top) {
    tioa::Automaton a("in");
    const auto done = a.boolean("done", false);
    a.input("go", {{"x", 0, top}, {"y", 0, top}}).eff([=](State& s, const tioa::Params&) {
      s[done] = true;
    });
    return a;
  };
  const auto noted = [](const PropertyResult& r) {
    return std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& note) {
      return note.find("input 'go' is open") != std::string::npos &&
             note.find("40000 points") != std::string::npos;
    });
  };
  CHECK(noted(check_no_deadlock(receiver(199), {})));
  CHECK_FALSE(noted(check_no_deadlock(receiver(49), {})));
  tioa::Automaton sender("out");
  sender.output("go", {{"x", 0, 199}, {"y", 0, 199}});
  const tioa::Automaton closed = tioa::compose("sys", {sender, receiver(199)});
  CHECK(check_no_deadlock(closed, {}).notes.empty());
}
