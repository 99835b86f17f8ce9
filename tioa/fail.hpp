#pragma once
// The failure transform Fail(A) of seed 000 §3.2.
//
// Fail(A) adds the discrete variable `failed` and the inputs fail and restart (named
// "fail_<A>" and "restart_<A>" unless given, so that components fail independently).
//  - start: `failed` arbitrary; when false the rest is a start state of A (any valuation
//    when true: the paper constrains only the non-failed case);
//  - (1) an ordinary input at a failed state leaves the state unchanged;
//  - (2) an ordinary input at a non-failed state is as in A;
//  - (3) fail sets failed := true;
//  - (4) restart at a failed state sets failed := false and the rest to a start state of
//    A (one successor per start state); at a non-failed state it changes nothing;
//  - outputs and internal actions of A are enabled only while not failed;
//  - trajectories: as A's while not failed; while failed every variable is frozen and
//    time passes freely.
// A is fail-transformable when it has no variable `failed` and no action of the two
// names; otherwise Fail throws a ModelError.

#include <string>

#include "tioa/automaton.hpp"

namespace tioa {

struct FailActions {
  std::string fail;    // default "fail_<A>"
  std::string restart; // default "restart_<A>"
};

Automaton Fail(const Automaton& a, FailActions names = {});

// The `failed` variable of Fail(a), for properties and tests.
Variable<bool> failed_variable(const Automaton& failed_automaton);

// Restart materialises A's start states; more than this is a ModelError.
inline constexpr std::size_t max_restart_states = std::size_t{1} << 22;

} // namespace tioa
