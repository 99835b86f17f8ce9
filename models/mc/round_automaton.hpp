#pragma once
// The round-level system (seed 002 §VI, seed 000 §6) as an automaton the checker can
// explore: one variable y[u] per region (robots assigned to region u at the start of a
// round) and one internal action `round` whose choices are the distinct outcomes of a
// round over every order of every VN's lower set (RoundSystem::all_next). Untimed: one
// step is one round, so a stabilisation check measures rounds.
//
// Start states: every distribution with at most `start_max` robots per region (the
// robots' failures and recoveries before round t0 leave any such distribution).

#include "models/mc/round.hpp"
#include "tioa/automaton.hpp"

namespace mc {

struct RoundAutomaton {
  tioa::Automaton automaton;
  tioa::VariableArray<int> y;
};

RoundAutomaton round_automaton(const RoundSystem& system, RobotCount start_max);

// The same with one start state, `start` (one count per region); std::invalid_argument when
// it does not fit the grid or holds more than max_automaton_robots robots.
inline constexpr RobotCount max_automaton_robots = 1'000'000'000;
RoundAutomaton round_automaton(const RoundSystem& system, const Counts& start);

// The counts of a state of the round automaton.
Counts counts_of(const tioa::VariableArray<int>& y, const tioa::State& s);

} // namespace mc
