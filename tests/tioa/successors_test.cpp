// The one-step semantics (tioa/successors.hpp): every action, parameter value and choice,
// then one tick of time.
#include <catch2/catch.hpp>

#include <algorithm>

#include "tests/tioa/helpers.hpp"

using namespace tioa;
using namespace tioa_test;

namespace {

// x ∈ 0..2 from 0: inc while x < 2, output reset at 2, input set(v) at any time.
struct Counter {
  Automaton a{"counter"};
  Variable<int> x = a.integer("x", 0, 2, 0);
  Counter() {
    const auto x = this->x;
    a.internal("inc")
        .pre([=](const State& s, const Params&) { return s[x] < 2; })
        .eff([=](State& s, const Params&) { s[x] = s[x] + 1; });
    a.output("reset")
        .pre([=](const State& s, const Params&) { return s[x] == 2; })
        .eff([=](State& s, const Params&) { s[x] = 0; });
    a.input("set", {{"v", 0, 2}}).eff([=](State& s, const Params& p) { s[x] = p[0]; });
  }
  Words with(int value) const {
    Words w(a.words(), 0);
    State(w.data(), 0)[x] = value;
    return w;
  }
};

// A clock c (cap 3) that must fire once it reaches 2: fire resets it and counts in n.
struct Timer {
  Automaton a{"timer"};
  Variable<int> c = a.clock("c", 3, 0);
  Variable<int> n = a.integer("n", 0, 3, 0);
  Timer() {
    const auto c = this->c, n = this->n;
    a.internal("fire")
        .pre([=](const State& s, const Params&) { return s[c] >= 2; })
        .eff([=](State& s, const Params&) {
          s[c] = 0;
          s[n] = std::min(3, s[n] + 1);
        });
    a.trajectories([=](State& s) { s.advance(c); }, [=](const State& s) { return s[c] >= 2; });
  }
  Words with(int clock) const {
    Words w(a.words(), 0);
    State(w.data(), 0)[c] = clock;
    return w;
  }
};

} // namespace

TEST_CASE("successors: exact successors and labels of a small automaton", "[tioa][successors]") {
  const Counter k;
  const auto from0 = steps(k.a, k.with(0));
  CHECK(labels(from0) == std::vector<std::string>{"inc", "set(0)", "set(1)", "set(2)"});
  REQUIRE(from0.size() == 4);
  CHECK(from0[0].state == k.with(1));
  CHECK(from0[1].state == k.with(0));
  CHECK(from0[2].state == k.with(1));
  CHECK(from0[3].state == k.with(2));

  const auto from2 = steps(k.a, k.with(2));
  CHECK(labels(from2) == std::vector<std::string>{"reset", "set(0)", "set(1)", "set(2)"});
  CHECK(from2[0].state == k.with(0));

  // Untimed: no tick, and the state the generator was given is not modified.
  const Words from = k.with(1);
  const auto from1 = steps(k.a, from);
  CHECK(labels(from1) == std::vector<std::string>{"inc", "set(0)", "set(1)", "set(2)"});
  CHECK(from == k.with(1));
  for (const auto& s : from1)
    CHECK_FALSE(s.tick);
}

TEST_CASE("successors: choose(n, ...) gives n successors", "[tioa][successors]") {
  Automaton a("dice");
  const auto v = a.integer("v", 0, 5, 0);
  a.internal("roll").choose(
      6, [=](State& s, const Params&, std::uint32_t choice) { s[v] = static_cast<int>(choice); });
  const auto list = steps(a, blank(a));
  REQUIRE(list.size() == 6);
  CHECK(list[0].label == "roll");
  CHECK(list[1].label == "roll [choice 1]");
  CHECK(list[5].label == "roll [choice 5]");
  for (int i = 0; i < 6; ++i)
    CHECK(value_of(list[i].state, v) == i);
}

TEST_CASE("successors: choices may depend on the state and the parameters", "[tioa][successors]") {
  Automaton a("fan");
  const auto v = a.integer("v", 0, 7, 2);
  a.internal("spread", {{"k", 0, 1}})
      .choose(
          [=](const State& s, const Params& p) { return static_cast<std::uint32_t>(s[v] + p[0]); },
          [=](State& s, const Params&, std::uint32_t choice) { s[v] = static_cast<int>(choice); });
  a.internal("stuck").choose(0, [](State&, const Params&, std::uint32_t) {});
  Words w = blank(a);
  State(w.data(), 0)[v] = 2;
  const auto list = steps(a, w);
  // k = 0: 2 choices, k = 1: 3 choices; stuck: none.
  CHECK(labels(list) == std::vector<std::string>{"spread(0)", "spread(0) [choice 1]", "spread(1)",
                                                 "spread(1) [choice 1]", "spread(1) [choice 2]"});
  CHECK(value_of(list[4].state, v) == 2);
  CHECK(value_of(list[3].state, v) == 1);
}

// A choice among copies held in the state: each slot that holds the wanted value is one
// choice, numbered by its slot; the action is enabled only where some slot holds it.
TEST_CASE("successors: choose_where gives the allowed choices, numbered as they are",
          "[tioa][successors]") {
  Automaton a("slots");
  const auto slot = a.integers("slot", 3, 0, 2, 0);
  a.internal("take", {{"v", 1, 2}})
      .choose_where(
          3,
          [=](const State& s, const Params& p, std::uint32_t c) {
            return s[slot[static_cast<int>(c)]] == p[0];
          },
          [=](State& s, const Params&, std::uint32_t c) { s[slot[static_cast<int>(c)]] = 0; });
  Words w = blank(a);
  CHECK(steps(a, w).empty()); // no slot holds 1 or 2: not enabled
  const ActionSignature& take = a.actions().front();
  Params p;
  p.size = 1;
  p.values[0] = 1;
  CHECK_FALSE(a.transitions().front().enabled(State(w.data(), 0), p));
  State(w.data(), 0)[slot[0]] = 1;
  State(w.data(), 0)[slot[2]] = 1;
  State(w.data(), 0)[slot[1]] = 2;
  CHECK(a.transitions().front().enabled(State(w.data(), 0), p));
  const auto list = steps(a, w);
  CHECK(labels(list) ==
        std::vector<std::string>{"take(1)", "take(1) [choice 2]", "take(2) [choice 1]"});
  REQUIRE(list.size() == 3);
  CHECK(value_of(list[0].state, slot[0]) == 0);
  CHECK(value_of(list[0].state, slot[2]) == 1);
  CHECK(value_of(list[1].state, slot[2]) == 0);
  CHECK(value_of(list[2].state, slot[1]) == 0);
  CHECK(take.name == "take");

  Automaton in("in");
  in.boolean("b", false);
  const std::string error = model_error([&] {
    in.input("go").choose_where(
        2, [](const State&, const Params&, std::uint32_t) { return true; },
        [](State&, const Params&, std::uint32_t) {});
  });
  CHECK_THAT(error, Catch::Contains("input 'go' cannot choose_where"));
}

TEST_CASE("successors: a disabled action and an empty box give no successor",
          "[tioa][successors]") {
  Automaton a("quiet");
  a.boolean("b", false);
  a.internal("never").pre([](const State&, const Params&) { return false; });
  a.internal("nobox", {{"i", 1, 0}});
  a.internal("only_odd", {{"i", 0, 3}}).pre([](const State&, const Params& p) {
    return p[0] % 2 == 1;
  });
  CHECK(labels(steps(a, blank(a))) == std::vector<std::string>{"only_odd(1)", "only_odd(3)"});
}

TEST_CASE("successors: a tick only when timed and stop_when is false", "[tioa][successors]") {
  const Timer t;
  // c = 0: no discrete step, one tick that applies evolve.
  const auto at0 = steps(t.a, t.with(0));
  REQUIRE(at0.size() == 1);
  CHECK(at0[0].tick);
  CHECK(at0[0].label == "tick");
  CHECK(at0[0].state == t.with(1));

  // c = 2: stop_when holds; fire is the only way on.
  const auto at2 = steps(t.a, t.with(2));
  REQUIRE(at2.size() == 1);
  CHECK(at2[0].label == "fire");
  CHECK(value_of(at2[0].state, t.c) == 0);
  CHECK(value_of(at2[0].state, t.n) == 1);

  // Timed with neither evolve nor stop_when: time always passes and changes nothing.
  Automaton idle("idle");
  idle.boolean("b", std::nullopt);
  idle.trajectories({});
  Words w = blank(idle);
  w[0] = 1;
  const auto ticks = steps(idle, w);
  REQUIRE(ticks.size() == 1);
  CHECK(ticks[0].tick);
  CHECK(ticks[0].state == trimmed(w.data(), idle.words()));
}

TEST_CASE("successors: duration is 1 for a tick and 0 for a discrete step when timed",
          "[tioa][successors]") {
  const Timer t;
  const SuccessorGenerator timed(t.a);
  CHECK(timed.timed());
  CHECK(timed.duration(StepLabel{}) == 1);
  StepLabel fire;
  fire.action = 0;
  CHECK(timed.duration(fire) == 0);
  for (const auto& s : steps(t.a, t.with(1)))
    CHECK(s.duration == (s.tick ? 1u : 0u));
  for (const auto& s : steps(t.a, t.with(2)))
    CHECK(s.duration == 0);

  // Untimed: every step takes one unit.
  const Counter k;
  const SuccessorGenerator untimed(k.a);
  CHECK_FALSE(untimed.timed());
  CHECK(untimed.duration(fire) == 1);
  for (const auto& s : steps(k.a, k.with(0)))
    CHECK(s.duration == 1);
}

TEST_CASE("successors: describe() names the action, its parameters and its choice",
          "[tioa][successors]") {
  const Counter k;
  const SuccessorGenerator g(k.a);
  StepLabel set;
  set.action = 2;
  set.params.size = 1;
  set.params.values[0] = 1;
  CHECK(g.describe(set) == "set(1)");
  set.choice = 2;
  CHECK(g.describe(set) == "set(1) [choice 2]");
  CHECK(g.describe(StepLabel{}) == "tick");
  CHECK(g.words() == k.a.words());
}
