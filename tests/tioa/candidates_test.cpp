// Binders (automaton.hpp) and the parameter values the generator tries (candidates.hpp).
#include <catch2/catch.hpp>

#include <vector>

#include "tioa/candidates.hpp"
#include "tioa/compose.hpp"
#include "tioa/fail.hpp"
#include "tioa/successors.hpp"

using namespace tioa;

namespace {

// `pick(i, j)` may take any i and the j that `target` holds (none while it is ⊥).
Automaton picker(const std::string& name, bool bound) {
  Automaton a(name);
  const auto target = a.optional_integer("target", 0, 3, 2);
  const auto picked = a.integer("picked", 0, 3, 0);
  auto pick = a.output("pick_" + name, {{"i", 0, 1}, {"j", 0, 3}});
  pick.pre([=](const State& s, const Params& p) {
        return !s.is_bottom(target) && p[1] == s[target];
      })
      .eff([=](State& s, const Params& p) {
        s[picked] = p[1];
        s.set_bottom(target);
      });
  if (bound)
    pick.bind("j", target);
  return a;
}

std::vector<Params> candidates(const Automaton& a, const std::vector<Word>& state) {
  std::vector<Params> out;
  const State s(state.data(), 0);
  for_each_candidate(a.actions()[0], a.transitions()[0], s,
                     [&](const Params& p) { out.push_back(p); });
  return out;
}

} // namespace

TEST_CASE("a bound parameter takes only its binder's value", "[candidates]") {
  const Automaton free = picker("p", false), bound = picker("p", true);
  std::vector<Word> state(2, 0);
  free.start().enumerate(state.data(), 0, [] {});
  CHECK(candidates(free, state).size() == 8);
  const auto tried = candidates(bound, state);
  REQUIRE(tried.size() == 2); // i = 0, 1 with j = 2, in lexicographic order
  CHECK(tried[0][0] == 0);
  CHECK(tried[0][1] == 2);
  CHECK(tried[1][0] == 1);
  CHECK(tried[1][1] == 2);
  // The same successors either way.
  const SuccessorGenerator with(bound), without(free);
  std::vector<Word> scratch(3, 0);
  std::vector<std::vector<Word>> a, b;
  with.successors(state.data(), scratch.data(),
                  [&](const Word* w, const StepLabel&) { a.emplace_back(w, w + 1); });
  without.successors(state.data(), scratch.data(),
                     [&](const Word* w, const StepLabel&) { b.emplace_back(w, w + 1); });
  CHECK(a == b);
  CHECK(a.size() == 2);
}

TEST_CASE("a binder with no value leaves no candidate", "[candidates]") {
  const Automaton bound = picker("p", true);
  std::vector<Word> state(2, 0);
  State s(state.data(), 0);
  s.set_bottom(find_variable<int>(bound, "target"));
  CHECK(candidates(bound, state).empty());
}

TEST_CASE("compose and Fail keep the owner's binders, read in the owner's part", "[candidates]") {
  const Automaton system = compose("two", {picker("a", true), Fail(picker("b", true))});
  const std::size_t b = *system.find_action("pick_b");
  std::vector<Word> state(2, 0);
  system.start().enumerate(state.data(), 0, [] {});
  State s(state.data(), 0);
  s.set(find_variable<int>(system, "b.target"), 1);
  std::vector<Params> tried;
  for_each_candidate(system.actions()[b], system.transitions()[b], s,
                     [&](const Params& p) { tried.push_back(p); });
  REQUIRE(tried.size() == 2);
  CHECK(tried[0][1] == 1);
}

TEST_CASE("binding is refused for inputs, unknown and twice-bound parameters", "[candidates]") {
  Automaton a("a");
  const auto v = a.integer("v", 0, 3, 0);
  CHECK_THROWS_WITH(a.input("in", {{"x", 0, 3}}).bind("x", v), Catch::Contains("cannot bind"));
  auto out = a.output("out", {{"x", 0, 3}});
  CHECK_THROWS_WITH(out.bind("y", v), Catch::Contains("no parameter 'y'"));
  out.bind("x", v);
  CHECK_THROWS_WITH(out.bind("x", v), Catch::Contains("bound twice"));
}
