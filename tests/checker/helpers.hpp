#pragma once
// Small automata whose state graphs can be worked out by hand, and helpers to build and
// read states, shared by the tests of checker/ and models/.

#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "checker/explorer.hpp"
#include "tioa/tioa.hpp"

namespace checker_test {

using tioa::Params;
using tioa::State;
using tioa::Word;
using Words = std::vector<Word>;

// Options with the partial-order reduction on or off.
inline checker::ExploreOptions with_por(bool on) {
  checker::ExploreOptions options;
  options.por = on;
  return options;
}

// A state of `a`: every variable at code 0, then `fill` applied.
inline Words make_state(const tioa::Automaton& a, const std::function<void(State&)>& fill) {
  Words w(a.words() + 1, 0);
  State s(w.data(), 0);
  fill(s);
  w.resize(a.words());
  return w;
}

// Where the variable called `name` lives in a state of `a`.
inline tioa::Slot slot_of(const tioa::Automaton& a, const std::string& name) {
  const tioa::VariableInfo* info = a.layout().find(name);
  if (!info)
    throw std::logic_error("test: no variable '" + name + "' in " + a.name());
  return info->slot();
}

// The slots of the variables of the array `name` (name[...]), in declaration order, so
// that tests do not depend on how an array numbers its items.
inline std::vector<tioa::Slot> slots_named(const tioa::Automaton& a, const std::string& name) {
  std::vector<tioa::Slot> out;
  for (const auto& v : a.layout().variables())
    if (v.name.rfind(name + "[", 0) == 0)
      out.push_back(v.slot());
  if (out.empty())
    throw std::logic_error("test: no array '" + name + "' in " + a.name());
  return out;
}

// The value of the variable called `name` in a state of `a`.
inline std::int64_t value_of(const tioa::Automaton& a, const Word* state, const std::string& name) {
  const tioa::VariableInfo* info = a.layout().find(name);
  if (!info)
    throw std::logic_error("test: no variable '" + name + "' in " + a.name());
  return info->lo + static_cast<std::int64_t>(State(state, 0).code(info->slot()));
}
inline std::int64_t value_of(const tioa::Automaton& a, const Words& state,
                             const std::string& name) {
  return value_of(a, state.data(), name);
}

inline Words stored(const checker::Exploration& ex, checker::StateId id) {
  return Words(ex.store.state(id), ex.store.state(id) + ex.store.words());
}

// `n` counters of 30 bits each, two to a word (so a word is 2^31 or more once the second
// counter of it is 2 or more: wide words, for the compressed store's tables), each counting
// up by one to `top`; with `wrap`, back from `top` to 0 ((top + 1)^n states, none stuck),
// else stopping there (every execution ends with all at the top, after n * top steps).
inline tioa::Automaton wide_counters(int n, int top, bool wrap) {
  tioa::Automaton c(wrap ? "wide-counters" : "wide-count-up");
  std::vector<tioa::Variable<int>> x;
  for (int i = 0; i < n; ++i)
    x.push_back(c.integer("x" + std::to_string(i), 0, (1 << 30) - 1, 0));
  for (int i = 0; i < n; ++i) {
    const auto xi = x[static_cast<std::size_t>(i)];
    c.internal("inc" + std::to_string(i))
        .pre([=](const State& s, const Params&) { return s[xi] < top; })
        .eff([=](State& s, const Params&) { s[xi] = s[xi] + 1; });
    if (wrap)
      c.internal("wrap" + std::to_string(i))
          .pre([=](const State& s, const Params&) { return s[xi] == top; })
          .eff([=](State& s, const Params&) { s[xi] = 0; });
  }
  return c;
}

// Breadth-first distances from the start states, by a plain search over std::map that
// shares nothing with the explorer but the one-step semantics.
inline std::map<Words, std::uint32_t> bfs_depths(const tioa::Automaton& a) {
  const tioa::SuccessorGenerator generator(a);
  const std::uint32_t words = a.words();
  std::map<Words, std::uint32_t> depth;
  std::deque<Words> todo;
  Words buffer(words + 1, 0);
  a.start().enumerate(buffer.data(), 0, [&] {
    Words s(buffer.begin(), buffer.begin() + words);
    if (depth.emplace(s, 0).second)
      todo.push_back(s);
  });
  Words from(words + 1, 0), scratch(words + 1, 0);
  while (!todo.empty()) {
    std::copy(todo.front().begin(), todo.front().end(), from.begin());
    const std::uint32_t d = depth.at(todo.front());
    todo.pop_front();
    generator.successors(from.data(), scratch.data(), [&](const Word* to, const tioa::StepLabel&) {
      Words t(to, to + words);
      if (depth.emplace(t, d + 1).second)
        todo.push_back(std::move(t));
    });
  }
  return depth;
}

// ---- tiny automata

// Two flags a, b from false; setA and setB each raise one. Four states, four edges:
//   (0,0) -setA-> (1,0), (0,0) -setB-> (0,1), (1,0) -setB-> (1,1), (0,1) -setA-> (1,1);
// (1,1) has no action: a deadlock.
inline tioa::Automaton diamond() {
  tioa::Automaton d("diamond");
  const auto a = d.boolean("a", false);
  const auto b = d.boolean("b", false);
  d.internal("setA")
      .pre([=](const State& s, const Params&) { return !s[a]; })
      .eff([=](State& s, const Params&) { s[a] = true; });
  d.internal("setB")
      .pre([=](const State& s, const Params&) { return !s[b]; })
      .eff([=](State& s, const Params&) { s[b] = true; });
  return d;
}

// x in 0..top, started anywhere (U); dec takes x to x-1, or also to x-2 when `jumps`.
// Untimed: each step is one unit, so from x the longest way to 0 is x steps.
inline tioa::Automaton countdown(int top, bool jumps = false) {
  tioa::Automaton c("countdown");
  const auto x = c.integer("x", 0, top, std::nullopt);
  c.internal("dec")
      .pre([=](const State& s, const Params&) { return s[x] > 0; })
      .choose([=](const State& s, const Params&) { return jumps && s[x] >= 2 ? 2u : 1u; },
              [=](State& s, const Params&, std::uint32_t choice) {
                s[x] = s[x] - 1 - static_cast<int>(choice);
              });
  return tioa::U(c);
}

// x in 0..top, started anywhere; each tick takes x one down (to 0 at the least). With
// `zeno`, a flag b that `flip` toggles in zero time while x > 0: a zero-time cycle.
inline tioa::Automaton timed_countdown(int top, bool zeno = false) {
  tioa::Automaton c("timed-countdown");
  const auto x = c.integer("x", 0, top, std::nullopt);
  if (zeno) {
    const auto b = c.boolean("b", std::nullopt);
    c.internal("flip")
        .pre([=](const State& s, const Params&) { return s[x] > 0; })
        .eff([=](State& s, const Params&) { s[b] = !s[b]; });
  }
  c.trajectories([=](State& s) {
    if (s[x] > 0)
      s[x] = s[x] - 1;
  });
  return tioa::U(c);
}

// The reachable states of `a` where time can pass (its stop-when condition is false),
// explored in full or with the zero-time reduction: the reduction must keep every one.
inline std::set<Words> time_passing_states(const tioa::Automaton& a, bool por) {
  const tioa::SuccessorGenerator generator(a);
  std::optional<checker::ZeroTimeReduction> reduction;
  if (por)
    reduction.emplace(generator, tioa::StatePredicate{});
  const checker::Exploration ex =
      checker::explore(generator, a.start(), checker::ExploreOptions{}, checker::hooks(),
                       reduction ? &*reduction : nullptr);
  std::set<Words> out;
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    const Word* s = ex.store.state(id);
    if (!a.trajectory().stops(State(s, 0)))
      out.emplace(s, s + a.words());
  }
  return out;
}

} // namespace checker_test
