#pragma once
// Dijkstra's K-state self-stabilising token ring, exactly as ../shared/peer-models.md (a).

#include <functional>

#include "tioa/automaton.hpp"

namespace token_ring {

struct TokenRing {
  tioa::Automaton system;                            // U(ring): every state is a start state
  std::function<int(const tioa::State&)> privileges; // how many processes are privileged
};

TokenRing build(int n, int k);

} // namespace token_ring
