#pragma once
// R(A) = Start(A, Reach_A) of seed 000 §3.3: A started in any state reachable from one of
// its start states. The reachable states are explored once and listed; an exploration
// that hits a limit is a ModelError (R(A) would be wrong, not just incomplete). It lists
// the states, so it needs the exact store (std::invalid_argument otherwise).

#include "checker/options.hpp"
#include "tioa/automaton.hpp"

namespace checker {

tioa::Automaton R(const tioa::Automaton& a, const ExploreOptions& options = {});

} // namespace checker
