#pragma once
// A small automaton with an unreachable value, for the start-set operators.

#include "tioa/tioa.hpp"

namespace tioa_test {

// x counts up to 2 from 0 (but could hold 3); at 2, b may be flipped.
struct Climb {
  tioa::Automaton a{"climb"};
  tioa::Variable<int> x = a.integer("x", 0, 3, 0);
  tioa::Variable<bool> b = a.boolean("b", false);
  Climb() {
    const auto x = this->x;
    const auto b = this->b;
    a.internal("up")
        .pre([=](const tioa::State& s, const tioa::Params&) { return s[x] < 2; })
        .eff([=](tioa::State& s, const tioa::Params&) { s[x] = s[x] + 1; });
    a.internal("flip")
        .pre([=](const tioa::State& s, const tioa::Params&) { return s[x] == 2; })
        .eff([=](tioa::State& s, const tioa::Params&) { s[b] = !s[b]; });
  }
  std::vector<tioa::Word> state(int xv, bool bv) const {
    std::vector<tioa::Word> w(a.words(), 0);
    tioa::State s(w.data(), 0);
    s[x] = xv;
    s[b] = bv;
    return w;
  }
};

} // namespace tioa_test
