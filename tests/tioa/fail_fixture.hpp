#pragma once
// A small timed automaton with every kind of action and two start states, for the tests
// of Fail, U and their commutation.

#include "tests/tioa/helpers.hpp"

namespace tioa_test {

// lamp: mode arbitrary at start (two start states), level 0..2 from 0, clock c (cap 2)
// from 0. Input set(v) sets the level, output shine lowers it, internal flip toggles the
// mode; time passes while c < 2.
struct Lamp {
  tioa::Automaton a{"lamp"};
  tioa::Variable<bool> mode = a.boolean("mode", std::nullopt);
  tioa::Variable<int> level = a.integer("level", 0, 2, 0);
  tioa::Variable<int> c = a.clock("c", 2, 0);

  Lamp() {
    using tioa::Params;
    using tioa::State;
    const auto mode = this->mode;
    const auto level = this->level, c = this->c;
    a.input("set", {{"v", 0, 2}}).eff([=](State& s, const Params& p) { s[level] = p[0]; });
    a.output("shine")
        .pre([=](const State& s, const Params&) { return s[level] > 0; })
        .eff([=](State& s, const Params&) { s[level] = s[level] - 1; });
    a.internal("flip").eff([=](State& s, const Params&) { s[mode] = !s[mode]; });
    a.trajectories([=](State& s) { s.advance(c); }, [=](const State& s) { return s[c] >= 2; });
  }

  // A state of `automaton` (A itself, or an automaton that keeps A's variables first and
  // adds `failed`, such as Fail(A)).
  Words state(const tioa::Automaton& automaton, bool m, int l, int clock,
              std::optional<bool> failed = std::nullopt) const {
    Words w(automaton.words(), 0);
    tioa::State s(w.data(), 0);
    s[mode] = m;
    s[level] = l;
    s[c] = clock;
    if (failed) {
      const auto flag = variable<bool>(automaton, "failed");
      s[flag] = *failed;
    }
    return w;
  }
};

} // namespace tioa_test
