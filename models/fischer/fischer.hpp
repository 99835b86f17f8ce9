#pragma once
// Fischer's mutual exclusion protocol in discrete time, exactly as
// ../shared/peer-models.md (b).

#include "tioa/automaton.hpp"

namespace fischer {

struct Fischer {
  tioa::Automaton system;
  tioa::StatePredicate at_most_one_in_cs; // mutual exclusion
};

Fischer build(int n, int a, int b);

} // namespace fischer
