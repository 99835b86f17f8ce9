#pragma once
// The start-set operators of seed 000 §3.3: Start(A, L) and U(A) = Start(A, Q_A).
// R(A) = Start(A, Reach_A) needs exploration and lives in checker/reach.hpp.

#include <string>

#include "tioa/automaton.hpp"

namespace tioa {

// A with start states L (every valuation satisfying `legal`).
inline Automaton Start(const Automaton& a, StatePredicate legal, std::string description) {
  Automaton out = a;
  out.set_start(StartSet::satisfying(a.layout(), std::move(legal), std::move(description)));
  return out;
}

inline Automaton Start(const Automaton& a, StartSet start) {
  Automaton out = a;
  out.set_start(std::move(start));
  return out;
}

// A started in any state: every valuation of its variables' finite domains.
inline Automaton U(const Automaton& a) {
  return Start(a, StartSet::every_valuation(a.layout()));
}

} // namespace tioa
