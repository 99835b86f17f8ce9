// Binders (automaton.hpp) and the parameter values the generator tries (candidates.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
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

// A small xorshift: the same random states on every run.
struct Xorshift {
  std::uint64_t seed;
  std::uint64_t operator()() {
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    return seed;
  }
};

// The first parameter of every step the generator takes from `state` (ticks left out).
std::vector<std::int32_t> generated_ids(const SuccessorGenerator& generator,
                                        const std::vector<Word>& state) {
  std::vector<std::int32_t> ids;
  std::vector<Word> scratch(generator.words() + 1, 0);
  generator.successors(state.data(), scratch.data(), [&](const Word*, const StepLabel& label) {
    if (!label.is_tick())
      ids.push_back(label.params[0]);
  });
  return ids;
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

namespace {

enum class Phase { idle, busy };

// `go(p)` may take a process p in 1..3 whose phase is idle; `filtered` says so with where().
Automaton starter(const std::string& name, bool filtered) {
  Automaton a(name);
  const auto phase = a.enumerations<Phase>("phase", ids(1, 3), {"IDLE", "BUSY"}, Phase::busy);
  auto go = a.internal("go_" + name, {{"p", 0, 4}}); // a box wider than the array
  go.pre([=](const State& s, const Params& x) {
      return x[0] >= 1 && x[0] <= 3 && s[phase[x[0]]] == Phase::idle;
    }).eff([=](State& s, const Params& x) { s[phase[x[0]]] = Phase::busy; });
  if (filtered)
    go.where("p", phase, Phase::idle);
  return a;
}

} // namespace

TEST_CASE("a filtered parameter takes only the ids whose variable holds the value",
          "[candidates]") {
  const Automaton free = starter("s", false), filtered = starter("s", true);
  std::vector<Word> state(2, 0); // (a spare word: GCC cannot see the layout)
  filtered.start().enumerate(state.data(), 0, [] {});
  CHECK(candidates(filtered, state).empty()); // every phase is BUSY at start
  State s(state.data(), 0);
  s.set(find_variable<Phase>(filtered, "phase[1]"), Phase::idle);
  s.set(find_variable<Phase>(filtered, "phase[3]"), Phase::idle);
  const auto tried = candidates(filtered, state);
  REQUIRE(tried.size() == 2);
  CHECK(tried[0][0] == 1);
  CHECK(tried[1][0] == 3);
  CHECK(candidates(free, state).size() == 5);
  // The same successors either way.
  const SuccessorGenerator with(filtered), without(free);
  std::vector<Word> scratch(3, 0);
  std::vector<Word> a, b;
  with.successors(state.data(), scratch.data(),
                  [&](const Word* w, const StepLabel&) { a.push_back(w[0]); });
  without.successors(state.data(), scratch.data(),
                     [&](const Word* w, const StepLabel&) { b.push_back(w[0]); });
  CHECK(a == b);
  CHECK(a.size() == 2);
  // What the reduction asks of one step (Binding::allows).
  const Binding& binding = filtered.transitions()[0].bindings.front();
  Params p;
  p.size = 1;
  for (const auto& [id, allowed] :
       {std::pair{0, false}, {1, true}, {2, false}, {3, true}, {4, false}}) {
    p.values[0] = id;
    CHECK(binding.allows(s, p) == allowed);
  }
}

TEST_CASE("compose and Fail keep a filter, read in the owner's part", "[candidates]") {
  const Automaton system = compose("two", {starter("a", true), Fail(starter("b", true))});
  const std::size_t b = *system.find_action("go_b");
  std::vector<Word> state(2, 0); // (a spare word: GCC cannot see the layout)
  system.start().enumerate(state.data(), 0, [] {});
  State s(state.data(), 0);
  s.set(find_variable<Phase>(system, "b.phase[2]"), Phase::idle);
  std::vector<Params> tried;
  for_each_candidate(system.actions()[b], system.transitions()[b], s,
                     [&](const Params& p) { tried.push_back(p); });
  REQUIRE(tried.size() == 1);
  CHECK(tried[0][0] == 2);
  const std::size_t a = *system.find_action("go_a");
  tried.clear();
  for_each_candidate(system.actions()[a], system.transitions()[a], s,
                     [&](const Params& p) { tried.push_back(p); });
  CHECK(tried.empty());
}

TEST_CASE("a filter is refused for inputs, a twice-bound parameter and a value outside the domain",
          "[candidates]") {
  Automaton a("a");
  const auto level = a.integers("level", ids(1, 2), 2, 5, 2);
  CHECK_THROWS_WITH(a.input("in", {{"p", 1, 2}}).where("p", level, 3),
                    Catch::Contains("cannot bind"));
  auto out = a.output("out", {{"p", 1, 2}});
  CHECK_THROWS_WITH(out.where("p", level, 6), Catch::Contains("outside the domain"));
  CHECK_THROWS_WITH(out.where("p", level, 1), Catch::Contains("outside the domain"));
  out.where("p", level, 5);
  out.where("p", level, std::vector<int>{4, 5}); // filters add up
  CHECK_THROWS_WITH(out.bind("p", [](const State&, const Params&) { return std::optional{1}; }),
                    Catch::Contains("bound twice"));
  CHECK_THROWS_WITH(a.output("out2", {{"p", 1, 2}}).where("p", level, std::vector<int>{}),
                    Catch::Contains("empty set of values"));
  CHECK_THROWS_WITH(a.output("out3", {{"p", 1, 2}}).where("p", level, std::vector<int>{4, 9}),
                    Catch::Contains("outside the domain"));
  auto bound = a.output("bound", {{"p", 1, 2}});
  bound.bind("p", [](const State&, const Params&) { return std::optional{1}; });
  CHECK_THROWS_WITH(bound.where("p", level, 3), Catch::Contains("bound twice"));
  CHECK_THROWS_WITH(a.internal("none", {{"p", 1, 2}}).where("p", VariableArray<int>{}, 0),
                    Catch::Contains("empty array"));
}

TEST_CASE("a filter over an array of fields side by side reads them at once, admitting the "
          "ids one by one would",
          "[candidates]") {
  Xorshift next{12345};
  for (const int values : {2, 3, 4, 5, 16}) // fields of 1, 2, 2, 3 and 4 bits
    for (const int count : {1, 5, 12, 21})
      for (const int pad : {0, 7, 50})           // bits before the array: a run across two words
        for (const bool apart : {false, true}) { // another array between its items
          INFO(values << " values, " << count << " ids, " << pad << " bits before, "
                      << (apart ? "apart" : "side by side"));
          Automaton a("filtered");
          for (int done = 0, k = 0; done < pad; ++k) { // variables of at most 20 bits
            const int bits = std::min(20, pad - done);
            a.integer("pad" + std::to_string(k), 0, (1 << bits) - 1, 0);
            done += bits;
          }
          VariableArray<int> level;
          if (apart) {
            level.first = 2;
            for (int i = 0; i < count; ++i) {
              level.items.push_back(
                  a.integer("level[" + std::to_string(i + 2) + "]", 0, values - 1, 0));
              a.integer("other[" + std::to_string(i) + "]", 0, 1, 0);
            }
          } else {
            level =
                a.integers("level", ids(2, static_cast<std::size_t>(count) + 1), 0, values - 1, 0);
          }
          a.internal("go", {{"p", 3, count + 4}}) // from the array's second id, past its last
              .where("p", level, values - 1);
          const Binding& b = a.transitions()[0].bindings.front();
          const int width = static_cast<int>(level.items.front().slot.width);
          CHECK(b.run.has_value() == ((count == 1 || !apart) && count * width <= 63));
          std::vector<Word> state(a.words() + 1, 0);
          const SuccessorGenerator generator(a);
          for (int round = 0; round < 50; ++round) {
            for (Word& w : state)
              w = next();
            const State s(state.data(), 0);
            std::vector<std::int32_t> expected, tried;
            for (int id = 3; id <= count + 1; ++id)
              if (s.code(level[static_cast<std::size_t>(id)].slot) ==
                  static_cast<std::uint64_t>(values - 1))
                expected.push_back(id);
            for (const Params& p : candidates(a, state))
              tried.push_back(p[0]);
            CHECK(tried == expected);
            // The generator's own reading of the run (SuccessorGenerator::RunFilter).
            CHECK(generated_ids(generator, state) == expected);
          }
        }
}

TEST_CASE("the generator reads a filter in the owner's part of a composition, as the candidate "
          "loop does",
          "[candidates]") {
  const Automaton filtered = compose("two", {starter("a", true), Fail(starter("b", true))});
  const Automaton free = compose("two", {starter("a", false), Fail(starter("b", false))});
  const SuccessorGenerator with(filtered), without(free);
  std::vector<Word> state(filtered.words() + 1, 0);
  filtered.start().enumerate(state.data(), 0, [] {});
  State s(state.data(), 0);
  const auto both = [&] {
    std::vector<Word> scratch(filtered.words() + 1, 0);
    std::vector<std::vector<Word>> a, b;
    with.successors(state.data(), scratch.data(), [&](const Word* w, const StepLabel&) {
      a.emplace_back(w, w + filtered.words());
    });
    without.successors(state.data(), scratch.data(), [&](const Word* w, const StepLabel&) {
      b.emplace_back(w, w + filtered.words());
    });
    CHECK(a == b);
    return a.size();
  };
  s.set(find_variable<bool>(filtered, "b.failed"), false);
  const std::size_t inputs = both(); // Fail's inputs; every phase is BUSY at start
  s.set(find_variable<Phase>(filtered, "b.phase[2]"), Phase::idle);
  CHECK(both() == inputs + 1);
  s.set(find_variable<Phase>(filtered, "a.phase[1]"), Phase::idle);
  s.set(find_variable<Phase>(filtered, "a.phase[3]"), Phase::idle);
  CHECK(both() == inputs + 3);
  s.set(find_variable<bool>(filtered, "b.failed"), true); // Fail(b) freezes go_b
  CHECK(both() == inputs + 2);
}

TEST_CASE("several filters on one parameter, each of several values, admit the ids every one "
          "admits, read at once or one by one",
          "[candidates]") {
  Xorshift next{4242};
  // level: 4 values (2 bits); clock: 4 values (2 bits, a run read with level's) or 8 (3
  // bits, read one by one); a third filter over `flag` (1 bit) read one by one; arrays
  // side by side or apart (no run: every filter one by one).
  for (const int clock_values : {4, 8})
    for (const bool apart : {false, true})
      for (const bool with_flag : {false, true}) {
        INFO(clock_values << " clock values, " << (apart ? "apart" : "side by side")
                          << (with_flag ? ", with a flag filter" : ""));
        Automaton a("filtered");
        VariableArray<int> level, clock;
        VariableArray<bool> flag;
        level.first = clock.first = flag.first = 1;
        if (apart) {
          for (int i = 1; i <= 9; ++i) {
            level.items.push_back(a.integer("level[" + std::to_string(i) + "]", 0, 3, 0));
            clock.items.push_back(
                a.integer("clock[" + std::to_string(i) + "]", 0, clock_values - 1, 0));
            flag.items.push_back(a.boolean("flag[" + std::to_string(i) + "]", false));
          }
        } else {
          level = a.integers("level", ids(1, 9), 0, 3, 0);
          clock = a.integers("clock", ids(1, 9), 0, clock_values - 1, 0);
          flag = a.booleans("flag", ids(1, 9), false);
        }
        const std::vector<int> levels{1, 3}, clocks{2, 3};
        const auto admitted = [&](const State& s, std::int32_t p) {
          const bool in_level =
              std::find(levels.begin(), levels.end(), s[level[p]]) != levels.end();
          const bool in_clock =
              std::find(clocks.begin(), clocks.end(), s[clock[p]]) != clocks.end();
          return in_level && in_clock && (!with_flag || s[flag[p]]);
        };
        auto go = a.internal("go", {{"p", 0, 8}}); // wider below, narrower above
        go.pre([=](const State& s, const Params& x) { return x[0] >= 1 && admitted(s, x[0]); })
            .where("p", level, levels)
            .where("p", clock, clocks);
        if (with_flag)
          go.where("p", flag, true);
        const auto& bindings = a.transitions()[0].bindings;
        REQUIRE(bindings.size() == (with_flag ? 3u : 2u));
        CHECK(bindings[0].run.has_value() == !apart);
        const SuccessorGenerator generator(a);
        std::vector<Word> state(a.words() + 1, 0);
        for (int round = 0; round < 300; ++round) {
          for (Word& w : state)
            w = next();
          const State s(state.data(), 0);
          std::vector<std::int32_t> expected, tried;
          for (std::int32_t p = 1; p <= 8; ++p)
            if (admitted(s, p))
              expected.push_back(p);
          for (const Params& p : candidates(a, state))
            tried.push_back(p[0]);
          CHECK(tried == expected);
          CHECK(generated_ids(generator, state) == expected);
          Params p;
          p.size = 1;
          for (std::int32_t id = 0; id <= 9; ++id) { // what the reduction asks of one step
            p.values[0] = id;
            const bool all = std::all_of(bindings.begin(), bindings.end(),
                                         [&](const Binding& b) { return b.allows(s, p); });
            CHECK(all == (id >= 1 && admitted(s, id)));
          }
        }
      }
}
