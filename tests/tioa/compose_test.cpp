// Composition and hiding (tioa/compose.hpp, seed 000 §3.1 "Composition").
#include <catch2/catch.hpp>

#include <algorithm>

#include "tests/tioa/helpers.hpp"

using namespace tioa;
using namespace tioa_test;
using Catch::Contains;

namespace {

// Outputs go(i) for i in lo..hi, once.
Automaton sender(const std::string& name, int lo, int hi) {
  Automaton a(name);
  const auto sent = a.boolean("sent", false);
  a.output("go", {{"i", lo, hi}})
      .pre([=](const State& s, const Params&) { return !s[sent]; })
      .eff([=](State& s, const Params&) { s[sent] = true; });
  return a;
}

// Receives go(i) for i in lo..hi and remembers the last i (-1: nothing yet).
Automaton receiver(const std::string& name, int lo, int hi) {
  Automaton a(name);
  const auto got = a.integer("got", -1, 9, -1);
  a.input("go", {{"i", lo, hi}}).eff([=](State& s, const Params& p) { s[got] = p[0]; });
  return a;
}

Automaton with_action(const std::string& name, ActionKind kind, const std::string& action) {
  Automaton a(name);
  a.boolean("b", false);
  switch (kind) {
  case ActionKind::input:
    a.input(action);
    break;
  case ActionKind::output:
    a.output(action);
    break;
  default:
    a.internal(action);
  }
  return a;
}

// A clock with a deadline: time cannot pass once the clock reaches `deadline` (if any).
Automaton timer(const std::string& name, int cap, std::optional<int> deadline) {
  Automaton a(name);
  const auto c = a.clock("c", cap, 0);
  StatePredicate stop;
  if (deadline)
    stop = [=, d = *deadline](const State& s) { return s[c] >= d; };
  a.trajectories([=](State& s) { s.advance(c); }, stop);
  return a;
}

// One node of a token ring: passes the token on with `out`, takes it with `in`, counts
// its turns, must pass within 2 quanta, and can be cleared by the environment.
Automaton ring_node(const std::string& name, const std::string& in, const std::string& out,
                    bool token) {
  Automaton a(name);
  const auto has = a.boolean("token", token);
  const auto turns = a.integer("turns", 0, 2, 0);
  const auto c = a.clock("c", 2, 0);
  a.output(out)
      .pre([=](const State& s, const Params&) { return s[has]; })
      .eff([=](State& s, const Params&) {
        s[has] = false;
        s[turns] = std::min(2, s[turns] + 1);
        s[c] = 0;
      });
  a.input(in).eff([=](State& s, const Params&) {
    s[has] = true;
    s[c] = 0;
  });
  a.input("clear").eff([=](State& s, const Params&) { s[turns] = 0; });
  a.internal("idle_" + name)
      .pre([=](const State& s, const Params&) { return !s[has] && s[turns] == 2; })
      .eff([=](State& s, const Params&) { s[turns] = 1; });
  a.trajectories([=](State& s) { s.advance(c); },
                 [=](const State& s) { return s[has] && s[c] >= 2; });
  return a;
}

std::vector<std::pair<std::string, ActionKind>> signature_of(const Automaton& a) {
  std::vector<std::pair<std::string, ActionKind>> out;
  for (const auto& s : a.actions())
    out.emplace_back(s.name, s.kind);
  return out;
}

} // namespace

TEST_CASE("compose: an output synchronises with every input whose box contains it",
          "[tioa][compose]") {
  const Automaton sys =
      compose("sys", {sender("s", 0, 2), receiver("all", 0, 2), receiver("one", 1, 1)});
  CHECK(sys.name() == "sys");
  // The matched input is not an input of the composite any more.
  CHECK(signature_of(sys) ==
        std::vector<std::pair<std::string, ActionKind>>{{"go", ActionKind::output}});
  const auto sent = variable<bool>(sys, "s.sent");
  const auto all = variable<int>(sys, "all.got");
  const auto one = variable<int>(sys, "one.got");

  const auto starts = start_states(sys);
  REQUIRE(starts.size() == 1);
  const auto list = steps(sys, starts[0]);
  REQUIRE(labels(list) == std::vector<std::string>{"go(0)", "go(1)", "go(2)"});
  for (int i = 0; i < 3; ++i) {
    CHECK(value_of(list[i].state, sent));
    CHECK(value_of(list[i].state, all) == i);
    // Only go(1) is in the box of "one".
    CHECK(value_of(list[i].state, one) == (i == 1 ? 1 : -1));
  }
  // After the one output nothing can happen.
  CHECK(steps(sys, list[1].state).empty());
  CHECK_FALSE(sys.timed());
}

TEST_CASE("compose: the order of components does not change who receives", "[tioa][compose]") {
  const Automaton sys = compose("sys", {receiver("one", 1, 1), sender("s", 0, 2)});
  const auto one = variable<int>(sys, "one.got");
  const auto list = steps(sys, start_states(sys).at(0));
  REQUIRE(list.size() == 3);
  CHECK(value_of(list[0].state, one) == -1);
  CHECK(value_of(list[1].state, one) == 1);
  CHECK(value_of(list[2].state, one) == -1);
}

TEST_CASE("compose: choices of the sender and the receivers multiply", "[tioa][compose]") {
  Automaton s("s");
  const auto a = s.integer("a", 0, 1, 0);
  s.output("go").choose(
      2, [=](State& st, const Params&, std::uint32_t k) { st[a] = static_cast<int>(k); });
  Automaton r("r");
  const auto b = r.integer("b", 0, 2, 0);
  r.input("go").choose(
      3, [=](State& st, const Params&, std::uint32_t k) { st[b] = static_cast<int>(k); });
  const Automaton sys = s || r;
  CHECK(sys.name() == "s||r");
  const auto list = steps(sys, start_states(sys).at(0));
  CHECK(list.size() == 6);
  std::set<std::pair<int, int>> pairs;
  for (const auto& step : list)
    pairs.emplace(value_of(step.state, variable<int>(sys, "s.a")),
                  value_of(step.state, variable<int>(sys, "r.b")));
  CHECK(pairs.size() == 6);
}

// The sender's choose_where is the lowest digit of the composed choice: a receiver's
// choices multiply only the sender's allowed ones.
TEST_CASE("compose: a sender's choose_where with a choosing receiver", "[tioa][compose]") {
  Automaton s("s");
  const auto a = s.integers("a", 3, 0, 1, 1);
  s.output("go").choose_where(
      3,
      [=](const State& st, const Params&, std::uint32_t k) {
        return st[a[static_cast<int>(k)]] == 1;
      },
      [=](State& st, const Params&, std::uint32_t k) { st[a[static_cast<int>(k)]] = 0; });
  Automaton r("r");
  const auto b = r.integer("b", 0, 1, 0);
  r.input("go").choose(
      2, [=](State& st, const Params&, std::uint32_t k) { st[b] = static_cast<int>(k); });
  const Automaton sys = s || r;
  Words w = start_states(sys).at(0);
  State(w.data(), 0)[variable<int>(sys, "s.a[1]")] = 0;
  const auto list = steps(sys, w);
  // Slots 0 and 2 hold 1, slot 1 does not: 2 sender choices × 2 receiver choices.
  CHECK(labels(list) ==
        std::vector<std::string>{"go", "go [choice 2]", "go [choice 3]", "go [choice 5]"});
  std::set<std::pair<int, int>> pairs;
  for (const auto& step : list)
    pairs.emplace(value_of(step.state, variable<int>(sys, "s.a[0]")),
                  value_of(step.state, variable<int>(sys, "r.b")));
  CHECK(pairs == std::set<std::pair<int, int>>{{0, 0}, {1, 0}, {0, 1}, {1, 1}});
}

TEST_CASE("compose: an input that is not enabled when delivered is a ModelError",
          "[tioa][compose]") {
  Automaton picky("picky");
  picky.boolean("b", false);
  picky.input("go", {{"i", 0, 2}}).pre([](const State&, const Params& p) { return p[0] != 1; });
  const Automaton sys = compose("sys", {sender("s", 0, 2), picky});
  const std::string error = model_error([&] { steps(sys, start_states(sys).at(0)); });
  CHECK_THAT(error, Contains("input enabling") && Contains("go(1)") && Contains("picky"));

  // The same for an input the environment drives.
  Automaton deaf("deaf");
  deaf.boolean("b", false);
  deaf.input("poke").pre([](const State&, const Params&) { return false; });
  const Automaton open = compose("open", {deaf, receiver("r", 0, 0)});
  CHECK_THAT(model_error([&] { steps(open, start_states(open).at(0)); }),
             Contains("input enabling") && Contains("deaf"));
}

TEST_CASE("compose: a composite's transition is flat, one part per author, Fail a flag",
          "[tioa][compose]") {
  const Automaton inner = compose("inner", {Fail(receiver("r1", 0, 2)), receiver("r2", 1, 1)});
  const Automaton sys = compose("sys", {Fail(sender("s", 0, 2)), inner});
  const std::size_t go = *sys.find_action("go");
  const Transition& t = sys.transitions()[go];
  // The sender's guard and effect, and each receiver's effect: no wrapper of a wrapper,
  // and not inner's environment owner, which does nothing.
  REQUIRE(t.parts.size() == 3);
  CHECK(t.parts[0].boxes.empty());
  CHECK(t.parts[0].frozen_by.size() == 1);
  CHECK(t.parts[0].frozen_by[0].offset == sys.layout().find("s.failed")->offset);
  CHECK(t.parts[1].frozen_by.size() == 1);
  CHECK(t.parts[1].frozen_by[0].offset == sys.layout().find("inner.r1.failed")->offset);
  CHECK(t.parts[1].boxes.size() == 2); // r1's own box, and inner's input go
  CHECK(t.parts[2].frozen_by.empty());
  CHECK(t.parts[2].base == sys.layout().find("inner.r2.got")->offset);

  // go(1) reaches both receivers, go(0) only r1; with r1 failed, r1 keeps its value.
  Words start = start_states(sys).at(0);
  const auto one = after(sys, start, "go(1)");
  const auto zero = after(sys, start, "go(0)");
  REQUIRE(one.size() == 1);
  REQUIRE(zero.size() == 1);
  CHECK(value_of(one[0], variable<int>(sys, "inner.r1.got")) == 1);
  CHECK(value_of(one[0], variable<int>(sys, "inner.r2.got")) == 1);
  CHECK(value_of(zero[0], variable<int>(sys, "inner.r1.got")) == 0);
  CHECK(value_of(zero[0], variable<int>(sys, "inner.r2.got")) == -1);
  view(start)[variable<bool>(sys, "inner.r1.failed")] = true;
  const auto frozen = after(sys, start, "go(1)");
  REQUIRE(frozen.size() == 1);
  CHECK(value_of(frozen[0], variable<int>(sys, "inner.r1.got")) == -1);
  CHECK(value_of(frozen[0], variable<int>(sys, "inner.r2.got")) == 1);
  // A failed sender sends nothing.
  view(start)[variable<bool>(sys, "s.failed")] = true;
  CHECK(after(sys, start, "go(1)").empty());
}

TEST_CASE("compose: an input not enabled deep in a nesting names its own component",
          "[tioa][compose]") {
  Automaton picky("picky");
  picky.boolean("b", false);
  picky.input("go", {{"i", 0, 2}}).pre([](const State&, const Params& p) { return p[0] != 1; });
  const Automaton sys = compose("sys", {sender("s", 0, 2), compose("inner", {picky})});
  CHECK_THAT(model_error([&] { steps(sys, start_states(sys).at(0)); }),
             Contains("go(1)") && Contains("'picky'"));
}

TEST_CASE("compose: a failed composition still takes the inputs its environment drives",
          "[tioa][compose]") {
  const Automaton failed = Fail(compose("pair", {receiver("r1", 0, 1), receiver("r2", 0, 1)}));
  Words start = start_states(failed).at(0);
  view(start)[variable<bool>(failed, "failed")] = true;
  for (const std::string go : {"go(0)", "go(1)"}) {
    const auto got = after(failed, start, go);
    REQUIRE(got.size() == 1); // taken, and nothing changes
    CHECK(got[0] == start);
  }
}

TEST_CASE("compose: the same component twice is incompatible (shared variables)",
          "[tioa][compose]") {
  const Automaton r = receiver("r", 0, 1);
  CHECK_THAT(model_error([&] {
               compose("twice", {r, r});
             }),
             Contains("incompatible") && Contains("'r'") && Contains("shared"));
  CHECK_THAT(model_error([&] { (void)(r || r); }), Contains("'r'"));
}

TEST_CASE("compose: two components outputting the same action are incompatible",
          "[tioa][compose]") {
  const std::string error = model_error([] {
    compose("two", {sender("s1", 0, 1), sender("s2", 1, 2)});
  });
  CHECK_THAT(error, Contains("incompatible") && Contains("'s1'") && Contains("'s2'") &&
                        Contains("both output 'go'"));
  CHECK_THAT(model_error([] {
               compose("two", {with_action("a", ActionKind::output, "x"),
                               with_action("b", ActionKind::output, "x")});
             }),
             Contains("both output 'x'"));
}

TEST_CASE("compose: an internal action of one that is an action of another is incompatible",
          "[tioa][compose]") {
  for (ActionKind other : {ActionKind::input, ActionKind::output, ActionKind::internal}) {
    const Automaton mine = with_action("mine", ActionKind::internal, "work");
    const Automaton theirs = with_action("theirs", other, "work");
    INFO("other kind: " << to_string(other));
    CHECK_THAT(model_error([&] {
                 compose("x", {mine, theirs});
               }),
               Contains("incompatible") && Contains("internal action 'work'") &&
                   Contains("'mine'") && Contains("'theirs'"));
    // Whatever the order.
    CHECK_THAT(model_error([&] {
                 compose("y", {theirs, mine});
               }),
               Contains("internal action 'work'"));
  }
}

TEST_CASE("compose: same-named outputs with disjoint parameter boxes are compatible",
          "[tioa][compose]") {
  Automaton sys("unset");
  REQUIRE_NOTHROW(
      sys = compose("sys", {sender("low", 0, 0), sender("high", 1, 2), receiver("r", 0, 2)}));
  const auto low = variable<bool>(sys, "low.sent");
  const auto high = variable<bool>(sys, "high.sent");
  const auto got = variable<int>(sys, "r.got");
  const auto list = steps(sys, start_states(sys).at(0));
  REQUIRE(labels(list) == std::vector<std::string>{"go(0)", "go(1)", "go(2)"});
  CHECK(value_of(list[0].state, low));
  CHECK_FALSE(value_of(list[0].state, high));
  CHECK_FALSE(value_of(list[2].state, low));
  CHECK(value_of(list[2].state, high));
  for (int i = 0; i < 3; ++i)
    CHECK(value_of(list[i].state, got) == i);
}

TEST_CASE("compose: unmatched inputs stay inputs, driven by the environment", "[tioa][compose]") {
  const Automaton sys = compose("sys", {receiver("all", 0, 2), receiver("one", 1, 1)});
  // One input for both, with the box that holds both.
  REQUIRE(sys.actions().size() == 1);
  CHECK(sys.actions()[0].kind == ActionKind::input);
  CHECK(sys.actions()[0].params.at(0).lo == 0);
  CHECK(sys.actions()[0].params.at(0).hi == 2);
  const auto all = variable<int>(sys, "all.got");
  const auto one = variable<int>(sys, "one.got");
  const auto list = steps(sys, start_states(sys).at(0));
  REQUIRE(labels(list) == std::vector<std::string>{"go(0)", "go(1)", "go(2)"});
  CHECK(value_of(list[0].state, all) == 0);
  CHECK(value_of(list[0].state, one) == -1);
  CHECK(value_of(list[1].state, all) == 1);
  CHECK(value_of(list[1].state, one) == 1);

  // A point of the merged box that no component receives is not offered.
  const Automaton apart = compose("apart", {receiver("a", 0, 0), receiver("b", 2, 2)});
  CHECK(labels(steps(apart, start_states(apart).at(0))) ==
        std::vector<std::string>{"go(0)", "go(2)"});

  // Different arities of one unmatched input are a ModelError.
  Automaton flat("flat");
  flat.boolean("b", false);
  flat.input("go");
  CHECK_THAT(model_error([&] {
               compose("arity", {receiver("r", 0, 1), flat});
             }),
             Contains("'go'") && Contains("arities"));
}

TEST_CASE("compose: time passes only when every timed component lets it", "[tioa][compose]") {
  Automaton untimed("plain");
  const auto flag = untimed.boolean("flag", false);
  untimed.internal("flip")
      .pre([=](const State& s, const Params&) { return !s[flag]; })
      .eff([=](State& s, const Params&) { s[flag] = true; });
  const Automaton sys = compose("sys", {timer("a", 3, 2), timer("b", 3, std::nullopt), untimed});
  REQUIRE(sys.timed());
  const auto ca = variable<int>(sys, "a.c");
  const auto cb = variable<int>(sys, "b.c");
  Words w = start_states(sys).at(0);
  std::vector<Step> list = steps(sys, w);
  CHECK(labels(list) == std::vector<std::string>{"flip", "tick"});
  // Evolve applies to every timed component.
  const Words after_tick = list.back().state;
  CHECK(value_of(after_tick, ca) == 1);
  CHECK(value_of(after_tick, cb) == 1);

  // a at its deadline: no tick, although b could let time pass.
  State(w.data(), 0)[ca] = 2;
  CHECK(labels(steps(sys, w)) == std::vector<std::string>{"flip"});
  // b at its cap does not stop time; it saturates while a advances.
  State(w.data(), 0)[ca] = 0;
  State(w.data(), 0)[cb] = 3;
  list = steps(sys, w);
  REQUIRE(list.back().tick);
  CHECK(value_of(list.back().state, ca) == 1);
  CHECK(value_of(list.back().state, cb) == 3);

  // Only untimed components: an untimed composite.
  CHECK_FALSE(compose("u", {untimed, receiver("r", 0, 0)}).timed());
}

TEST_CASE("compose: the start set is the product of the components' start sets",
          "[tioa][compose]") {
  Automaton a("a");
  a.boolean("p", std::nullopt); // 2 start states
  Automaton b("b");
  b.integer("x", 0, 2, std::nullopt); // 3 start states
  b.integer("y", 5, 6, 6);
  Automaton c("c");
  c.clock("k", 1, std::nullopt, true); // 3 start states: 0, 1, ⊥
  const Automaton sys = compose("sys", {a, b, c});
  const auto list = start_states(sys);
  CHECK(list.size() == 2 * 3 * 3);
  CHECK(std::set<Words>(list.begin(), list.end()).size() == list.size());
  for (const auto& w : list)
    CHECK(value_of(w, variable<int>(sys, "b.y")) == 6);

  // A component started elsewhere keeps its own start set in the product.
  Automaton u = b;
  u.set_start(StartSet::every_valuation(b.layout()));
  CHECK(start_states(compose("sys2", {a, u})).size() == 2 * 3 * 2);
}

TEST_CASE("hide: an output becomes an internal action; anything else is refused",
          "[tioa][compose]") {
  const Automaton s = sender("s", 0, 1);
  const Automaton hidden = hide(s, {"go"});
  REQUIRE(hidden.actions().size() == 1);
  CHECK(hidden.actions()[0].kind == ActionKind::internal);
  CHECK(s.actions()[0].kind == ActionKind::output); // the original is unchanged
  // The transitions are unchanged.
  CHECK(labels(steps(hidden, start_states(hidden).at(0))) ==
        std::vector<std::string>{"go(0)", "go(1)"});

  CHECK_THAT(model_error([&] { hide(s, {"nope"}); }), Contains("cannot hide 'nope'"));
  CHECK_THAT(model_error([] { hide(receiver("r", 0, 1), {"go"}); }), Contains("cannot hide 'go'"));
  CHECK_THAT(model_error([] { hide(with_action("i", ActionKind::internal, "w"), {"w"}); }),
             Contains("cannot hide 'w'"));

  // A hidden output no longer reaches other components: composing them is incompatible.
  CHECK_THAT(model_error([&] {
               compose("x", {hidden, receiver("r", 0, 1)});
             }),
             Contains("internal action 'go'"));
  // Hiding inside a composite.
  const Automaton sys = hide(compose("sys", {s, receiver("r", 0, 1)}), {"go"});
  CHECK(sys.actions()[0].kind == ActionKind::internal);
  CHECK(steps(sys, start_states(sys).at(0)).size() == 2);
}

TEST_CASE("hide: every action of the hidden name becomes internal", "[tioa][compose]") {
  // Regression: two components output go with disjoint boxes, so the composite has two
  // actions named go; hide() once looked up only the first and left the other an output.
  const Automaton sys =
      compose("sys", {sender("low", 0, 0), sender("high", 1, 2), receiver("r", 0, 2)});
  const Automaton hidden = hide(sys, {"go"});
  for (const auto& action : hidden.actions()) {
    INFO(action.label(Params{}) << " " << to_string(action.kind));
    CHECK(action.kind == ActionKind::internal);
  }
}

namespace {
const Automaton ring_a = ring_node("A", "c2a", "a2b", true);
const Automaton ring_b = ring_node("B", "a2b", "b2c", false);
const Automaton ring_c = ring_node("C", "b2c", "c2a", false);
} // namespace

TEST_CASE("compose: three components at once and nested compositions agree", "[tioa][compose]") {
  const Automaton flat = compose("ring", {ring_a, ring_b, ring_c});
  const Automaton left = compose("ring", {ring_a || ring_b, ring_c});
  const Automaton right = compose("ring", {ring_a, ring_b || ring_c});
  // The variables are laid out in the same order, so states compare bit for bit.
  REQUIRE(flat.layout().bits() == left.layout().bits());
  REQUIRE(flat.layout().bits() == right.layout().bits());
  CHECK(left.layout().find("A||B.A.token") != nullptr);

  const Reachable f = reachable(flat);
  const Reachable l = reachable(left);
  const Reachable r = reachable(right);
  // Pinned, and confirmed by an independent enumeration of the same ring by hand.
  CHECK(f.states.size() == 198);
  CHECK(f.transitions.size() == 705);
  CHECK(l.states == f.states);
  CHECK(r.states == f.states);
  CHECK(l.transitions == f.transitions);
  CHECK(r.transitions == f.transitions);

  // The token moves around the ring: after a2b, B holds it.
  const auto start = start_states(flat).at(0);
  const auto passed = after(flat, start, "a2b");
  REQUIRE(passed.size() == 1);
  CHECK_FALSE(value_of(passed[0], variable<bool>(flat, "A.token")));
  CHECK(value_of(passed[0], variable<bool>(flat, "B.token")));
  CHECK(value_of(passed[0], variable<int>(flat, "A.turns")) == 1);
  // clear is an input of all three, driven by the environment, in every composite.
  CHECK(after(flat, start, "clear").size() == 1);
  CHECK(after(left, start, "clear").size() == 1);
}

TEST_CASE("compose: nesting agrees with a flat composition when merged input boxes have gaps",
          "[tioa][compose]") {
  // Regression: a receives go(0), b receives go(2), c outputs go(1). Flat: go(1) happens
  // and reaches nobody; go(0) and go(2) stay inputs, driven by the environment. Nested:
  // a||b once had one input go over the merged box 0..2 that could not take go(1), which
  // threw "not enabled" or blocked c's output. Now a||b accepts exactly {0, 2}.
  const Automaton a = receiver("a", 0, 0), b = receiver("b", 2, 2), c = sender("c", 1, 1);
  const Automaton flat = compose("sys", {a, b, c});
  const Automaton nested = compose("sys", {a || b, c});
  const auto start = start_states(flat).at(0);
  REQUIRE(labels(steps(flat, start)) == std::vector<std::string>{"go(1)", "go(0)", "go(2)"});
  std::vector<Step> nested_steps;
  CHECK(model_error([&] { nested_steps = steps(nested, start); }) == "<no ModelError>");
  CHECK(nested_steps == steps(flat, start));
}

TEST_CASE("compose: an input stays an input where no output covers its parameters",
          "[tioa][compose]") {
  // Regression: a outputs go(0); b receives go(5). go(5) is not an output of a||b, so by
  // §3.1 it is still an input of a||b. compose() once dropped every input whose name some
  // component outputs, so e's go(5) reached b in compose({a, b, e}) but not in (a||b)||e.
  const Automaton a = sender("a", 0, 0), b = receiver("b", 5, 5), e = sender("e", 5, 5);
  const Automaton ab = a || b;
  bool has_input = false;
  for (const auto& action : ab.actions())
    has_input = has_input || (action.kind == ActionKind::input && action.name == "go");
  CHECK(has_input);
  const Reachable flat = reachable(compose("sys", {a, b, e}));
  const Reachable nested = reachable(compose("sys", {ab, e}));
  CHECK(nested.states == flat.states);
}

TEST_CASE("compose: an input box too large to enumerate is dropped when an output box holds it",
          "[tioa][compose]") {
  // Regression: vn-layer's send_target_update has one parameter per CN over the lattice's
  // points; with 3 CNs and b = 8, 154³ points. The box was too large to check point by point,
  // so the input stayed, and the explorer tried all 3.6 million points in every state.
  const auto wide = [](const std::string& name, ActionKind kind, int top) {
    Automaton a(name);
    const auto done = a.boolean("done", false);
    const std::vector<ParamRange> box{{"x", 0, 199}, {"y", 0, 199}, {"z", 0, top}};
    if (kind == ActionKind::output)
      a.output("go", box)
          .pre([=](const State& s, const Params&) { return !s[done]; })
          .eff([=](State& s, const Params&) { s[done] = true; });
    else
      a.input("go", box).eff([=](State& s, const Params&) { s[done] = true; });
    return a;
  };
  const auto has_input = [](const Automaton& a) {
    return std::any_of(a.actions().begin(), a.actions().end(), [](const ActionSignature& sig) {
      return sig.kind == ActionKind::input && sig.name == "go";
    });
  };
  CHECK_FALSE(has_input(
      compose("sys", {wide("out", ActionKind::output, 199), wide("in", ActionKind::input, 199)})));
  // An output box one value short in one parameter leaves the input in place.
  CHECK(has_input(
      compose("sys", {wide("out", ActionKind::output, 198), wide("in", ActionKind::input, 199)})));
}

TEST_CASE("compose: an environment input reaches all of 64 components", "[tioa][compose]") {
  // Regression: compose() allows 64 components; an unmatched input shared by all of them
  // has 65 participants (the environment and 64 receivers), and synchronised() once kept
  // counts for at most 64 and silently skipped the last receiver.
  std::vector<Automaton> parts;
  for (int i = 0; i < 64; ++i) {
    Automaton a(numbered("n", i));
    const auto got = a.boolean("got", false);
    a.input("go").eff([=](State& s, const Params&) { s[got] = true; });
    parts.push_back(a);
  }
  const Automaton sys = compose("many", parts);
  const auto list = steps(sys, start_states(sys).at(0));
  REQUIRE(list.size() == 1);
  for (int i = 0; i < 64; ++i) {
    INFO("component n" << i);
    CHECK(value_of(list[0].state, variable<bool>(sys, numbered("n", i, ".got"))));
  }
}

TEST_CASE("compose: no components, or more than 64, is a ModelError", "[tioa][compose]") {
  CHECK_THAT(model_error([] { compose("none", {}); }), Contains("no components"));
  std::vector<Automaton> parts;
  for (int i = 0; i < 65; ++i)
    parts.push_back(receiver(numbered("r", i), 0, 0));
  CHECK_THAT(model_error([&] { compose("too-many", parts); }), Contains("64"));
}
