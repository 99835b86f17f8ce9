// The failure transform Fail(A) (tioa/fail.hpp), one test per rule of seed 000 §3.2.
#include <catch2/catch.hpp>

#include <algorithm>

#include "tests/tioa/fail_fixture.hpp"

using namespace tioa;
using namespace tioa_test;
using Catch::Contains;

TEST_CASE("Fail: adds failed and the two inputs, keeps A's variables where they were",
          "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  CHECK(f.name() == "lamp");
  CHECK(f.timed());
  const auto failed = failed_variable(f);
  CHECK(failed.slot.offset == lamp.a.layout().bits());
  CHECK(f.layout().bits() == lamp.a.layout().bits() + 1);
  CHECK(variable<int>(f, "level").slot.offset == lamp.level.slot.offset);
  CHECK(variable<int>(f, "c").slot.offset == lamp.c.slot.offset);

  std::vector<std::pair<std::string, ActionKind>> sig;
  for (const auto& s : f.actions())
    sig.emplace_back(s.name, s.kind);
  CHECK(sig ==
        std::vector<std::pair<std::string, ActionKind>>{{"set", ActionKind::input},
                                                        {"shine", ActionKind::output},
                                                        {"flip", ActionKind::internal},
                                                        {"fail_lamp", ActionKind::input},
                                                        {"restart_lamp", ActionKind::input}});

  const Automaton named = Fail(lamp.a, {"crash", "recover"});
  CHECK(named.find_action("crash").has_value());
  CHECK(named.find_action("recover").has_value());
  CHECK_FALSE(named.find_action("fail_lamp").has_value());

  CHECK_THAT(model_error([&] { failed_variable(lamp.a); }), Contains("'failed'"));
}

TEST_CASE("Fail rule (1): an ordinary input at a failed state leaves the state unchanged",
          "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  const Words w = lamp.state(f, true, 1, 1, true);
  for (int v = 0; v <= 2; ++v) {
    const auto next = after(f, w, numbered("set(", v, ")"));
    REQUIRE(next.size() == 1);
    CHECK(next[0] == w);
  }

  // Even an input that A itself refuses (A is not input-enabled here on purpose) is
  // accepted and ignored while failed.
  Automaton choosy("choosy");
  const auto x = choosy.integer("x", 0, 3, 0);
  choosy.input("put", {{"v", 0, 3}})
      .pre([](const State&, const Params& p) { return p[0] != 3; })
      .eff([=](State& s, const Params& p) { s[x] = p[0]; });
  const Automaton fc = Fail(choosy);
  Words down = blank(fc);
  State(down.data(), 0)[failed_variable(fc)] = true;
  CHECK(labels(steps(fc, trimmed(down.data(), fc.words()))) ==
        std::vector<std::string>{"put(0)", "put(1)", "put(2)", "put(3)", "fail_choosy",
                                 "restart_choosy"});
  for (const auto& next : after(fc, trimmed(down.data(), fc.words()), "put(3)"))
    CHECK(next == trimmed(down.data(), fc.words()));
}

TEST_CASE("Fail rule (2): an ordinary input at a non-failed state is as in A", "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  const Words w = lamp.state(f, false, 1, 1, false);
  const auto next = after(f, w, "set(2)");
  REQUIRE(next.size() == 1);
  CHECK(next[0] == lamp.state(f, false, 2, 1, false));

  // For every state of A and every input: the same successors, with failed still false.
  const auto failed = failed_variable(f);
  for (const auto& a_state :
       enumerate(StartSet::every_valuation(lamp.a.layout()), lamp.a.words())) {
    Words fw = blank(f);
    copy_bits(fw.data(), 0, a_state.data(), 0, lamp.a.layout().bits());
    fw.resize(f.words());
    for (int v = 0; v <= 2; ++v) {
      const std::string label = numbered("set(", v, ")");
      const auto in_a = after(lamp.a, a_state, label);
      const auto in_f = after(f, fw, label);
      REQUIRE(in_a.size() == 1);
      REQUIRE(in_f.size() == 1);
      CHECK_FALSE(value_of(in_f[0], failed));
      CHECK(bits_at(in_f[0], 0, lamp.a.layout().bits()) ==
            bits_at(in_a[0], 0, lamp.a.layout().bits()));
    }
  }
}

TEST_CASE("Fail rule (3): fail sets failed := true and nothing else", "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  const auto up = after(f, lamp.state(f, true, 2, 1, false), "fail_lamp");
  REQUIRE(up.size() == 1);
  CHECK(up[0] == lamp.state(f, true, 2, 1, true));
  // fail at a failed state: still failed, nothing else changes.
  const auto down = after(f, lamp.state(f, false, 1, 2, true), "fail_lamp");
  REQUIRE(down.size() == 1);
  CHECK(down[0] == lamp.state(f, false, 1, 2, true));
}

TEST_CASE("Fail rule (4): restart resets a failed state to each start state of A", "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  REQUIRE(start_states(lamp.a).size() == 2);

  // Failed: one successor per start state of A (mode false or true, level 0, c 0).
  const Words down = lamp.state(f, true, 2, 1, true);
  std::vector<Words> restarted;
  for (const auto& s : steps(f, down))
    if (s.label.rfind("restart_lamp", 0) == 0)
      restarted.push_back(s.state);
  REQUIRE(restarted.size() == 2);
  CHECK(std::set<Words>(restarted.begin(), restarted.end()) ==
        std::set<Words>{lamp.state(f, false, 0, 0, false), lamp.state(f, true, 0, 0, false)});

  // Not failed: restart changes nothing, and there is exactly one such step.
  const Words up = lamp.state(f, true, 2, 1, false);
  const auto same = after(f, up, "restart_lamp");
  REQUIRE(same.size() == 1);
  CHECK(same[0] == up);
  CHECK(after(f, up, "restart_lamp [choice 1]").empty());
}

TEST_CASE("Fail: outputs and internal actions are disabled while failed", "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  CHECK(labels(steps(f, lamp.state(f, false, 1, 1, false))) ==
        std::vector<std::string>{"set(0)", "set(1)", "set(2)", "shine", "flip", "fail_lamp",
                                 "restart_lamp", "tick"});
  CHECK(labels(steps(f, lamp.state(f, false, 1, 1, true))) ==
        std::vector<std::string>{"set(0)", "set(1)", "set(2)", "fail_lamp", "restart_lamp",
                                 "restart_lamp [choice 1]", "tick"});
}

TEST_CASE("Fail: not failed, the trajectories are A's (evolve and stop_when)", "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  const auto ticks = [](const std::vector<Step>& list) {
    std::vector<Words> out;
    for (const auto& s : list)
      if (s.tick)
        out.push_back(s.state);
    return out;
  };
  // c = 1: one tick, evolve advances c.
  CHECK(ticks(steps(f, lamp.state(f, true, 1, 1, false))) ==
        std::vector<Words>{lamp.state(f, true, 1, 2, false)});
  // c = 2: A's stop_when holds, so no time passes.
  CHECK(ticks(steps(f, lamp.state(f, true, 1, 2, false))).empty());

  // For every state of A: a tick in Fail(A) (not failed) exactly when A has one, to the
  // same state.
  for (const auto& a_state :
       enumerate(StartSet::every_valuation(lamp.a.layout()), lamp.a.words())) {
    Words fw = blank(f);
    copy_bits(fw.data(), 0, a_state.data(), 0, lamp.a.layout().bits());
    fw.resize(f.words());
    const auto in_a = ticks(steps(lamp.a, a_state));
    const auto in_f = ticks(steps(f, fw));
    REQUIRE(in_a.size() == in_f.size());
    if (!in_a.empty())
      CHECK(bits_at(in_f[0], 0, f.layout().bits()) == bits_at(in_a[0], 0, lamp.a.layout().bits()));
  }
}

TEST_CASE("Fail: failed, the state is frozen and time passes even when A's stop_when holds",
          "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  for (int c = 0; c <= 2; ++c) {
    const Words down = lamp.state(f, false, 2, c, true);
    std::vector<Words> ticks;
    for (const auto& s : steps(f, down))
      if (s.tick)
        ticks.push_back(s.state);
    INFO("c = " << c);
    REQUIRE(ticks.size() == 1);
    CHECK(ticks[0] == down);
  }
}

TEST_CASE("Fail: start states are failed = false with A's, or failed = true with any",
          "[tioa][fail]") {
  const Lamp lamp;
  const Automaton f = Fail(lamp.a);
  const auto failed = failed_variable(f);
  const auto list = start_states(f);
  // 2 start states of A, and 2 × 3 × 3 valuations of A's variables while failed.
  CHECK(list.size() == 2 + 18);
  CHECK(std::set<Words>(list.begin(), list.end()).size() == list.size());
  std::set<Words> up, down;
  for (const auto& w : list)
    (value_of(w, failed) ? down : up).insert(w);
  CHECK(up == std::set<Words>{lamp.state(f, false, 0, 0, false), lamp.state(f, true, 0, 0, false)});
  CHECK(down.size() == 18);
  for (const auto& w : down)
    CHECK(value_of(w, failed));
  CHECK(down.count(lamp.state(f, true, 2, 2, true)) == 1);
  CHECK(down.count(lamp.state(f, false, 0, 0, true)) == 1);

  // A with a single start state.
  Automaton one("one");
  one.integer("x", 0, 4, 2);
  CHECK(start_states(Fail(one)).size() == 1 + 5);
}

TEST_CASE("Fail: an automaton that is not fail-transformable is a ModelError", "[tioa][fail]") {
  Automaton has_failed("broken");
  has_failed.boolean("failed", false);
  CHECK_THAT(model_error([&] { Fail(has_failed); }),
             Contains("not fail-transformable") && Contains("'failed'"));

  Automaton has_fail("lamp");
  has_fail.boolean("b", false);
  has_fail.input("fail_lamp");
  CHECK_THAT(model_error([&] { Fail(has_fail); }),
             Contains("not fail-transformable") && Contains("'fail_lamp'"));

  Automaton has_restart("lamp");
  has_restart.boolean("b", false);
  has_restart.internal("restart_lamp");
  CHECK_THAT(model_error([&] { Fail(has_restart); }),
             Contains("not fail-transformable") && Contains("'restart_lamp'"));

  // With names given, those names are the ones that must be free.
  Automaton has_crash("lamp");
  has_crash.boolean("b", false);
  has_crash.output("crash");
  CHECK_THAT(model_error([&] { Fail(has_crash, {"crash", "recover"}); }), Contains("'crash'"));
  CHECK_NOTHROW(Fail(has_crash, {"down", "up"}));
  CHECK_NOTHROW(Fail(has_fail, {"down", "up"}));

  // Fail(Fail(A)) is refused: the first transform added 'failed'.
  CHECK_THAT(model_error([&] {
               Fail(Fail(has_crash, {"down", "up"}), {"down2", "up2"});
             }),
             Contains("'failed'"));
}

TEST_CASE("Fail: an untimed automaton stays untimed", "[tioa][fail]") {
  Automaton a("steps");
  const auto x = a.integer("x", 0, 1, 0);
  a.internal("go").eff([=](State& s, const Params&) { s[x] = 1; });
  const Automaton f = Fail(a);
  CHECK_FALSE(f.timed());
  Words down = blank(f);
  State(down.data(), 0)[failed_variable(f)] = true;
  // Failed and untimed: only the inputs (fail, restart) are possible.
  CHECK(labels(steps(f, trimmed(down.data(), f.words()))) ==
        std::vector<std::string>{"fail_steps", "restart_steps"});
}

TEST_CASE("Fail: components fail independently in a composition", "[tioa][fail]") {
  Automaton s("s");
  const auto sent = s.boolean("sent", false);
  s.output("go")
      .pre([=](const State& st, const Params&) { return !st[sent]; })
      .eff([=](State& st, const Params&) { st[sent] = true; });
  Automaton r("r");
  const auto got = r.boolean("got", false);
  r.input("go").eff([=](State& st, const Params&) { st[got] = true; });

  const Automaton sys = compose("sys", {Fail(s), Fail(r)});
  CHECK(sys.find_action("fail_s").has_value());
  CHECK(sys.find_action("fail_r").has_value());
  const auto r_failed = variable<bool>(sys, "r.failed");
  const auto s_failed = variable<bool>(sys, "s.failed");
  const auto r_got = variable<bool>(sys, "r.got");
  const auto s_sent = variable<bool>(sys, "s.sent");

  // From the start state where only r is failed: go is sent and r ignores it (rule 1).
  Words start;
  for (const auto& w : start_states(sys))
    if (value_of(w, r_failed) && !value_of(w, s_failed) && !value_of(w, r_got) &&
        !value_of(w, s_sent))
      start = w;
  REQUIRE_FALSE(start.empty());
  const auto sent_state = after(sys, start, "go");
  REQUIRE(sent_state.size() == 1);
  CHECK(value_of(sent_state[0], s_sent));
  CHECK_FALSE(value_of(sent_state[0], r_got));
  // Failing s disables its output.
  const auto s_down = after(sys, start, "fail_s");
  REQUIRE(s_down.size() == 1);
  CHECK(after(sys, s_down[0], "go").empty());
}
