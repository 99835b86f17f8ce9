#pragma once
// Stabilisation from a set of start states too large to list (10^16 and more), decided
// symbolically and exactly: the worst time after which every execution from every start
// state is in L, as check_stabilisation (checks.hpp) measures it state by state.
//
// Over discretised time the states an execution can be in at time k are the layer
//   X_0 = the zero-time closure of the start states,  X_{k+1} = the zero-time closure of
//   one tick from X_k,
// and those it can be in at any time >= k are A_k = everything reachable from X_k. The worst
// time is the least k with A_k inside L: the layers are computed one by one, and only a
// layer inside L is followed further, inside L only, until a step leaves L (A_k is then not
// inside) or nothing new comes (System::stays_within).
// There are finitely many sets, so the layers repeat at last (X_k = X_j, j < k); from j on
// they go round, A_j is the union of the period, and if no earlier k ended the search that
// union has a state outside L: an execution outside L at every time, no worst time.
//
// Time-locks (states from which no tick can come) and states from which zero-time steps can
// go on for ever are found too: an execution that stops time is not one the layers judge, so
// the caller must not claim more than "no such state" allows. Both are cheap when the
// zero-time steps are proved free of cycles (symbolic_acyclic.hpp) and no reachable state
// is stuck: then there is neither. The start state of a worst case is picked by going back
// through the layers.

#include <cstdint>
#include <optional>
#include <vector>

#include "checker/symbolic_system.hpp"

namespace checker::symbolic {

struct StabilisationResult {
  double start_states = 0;
  double reachable = 0;               // from the start states, every time
  std::optional<std::uint64_t> worst; // nullopt: outside L at every time
  std::uint64_t layers = 0;           // X_0 .. X_{layers - 1} computed
  double late_outside = 0;            // states outside L at time >= worst - 1 (when picked)
  std::vector<Word> worst_start;      // a start state with an execution outside L at time
                                      // worst - 1 (or at every time): when the worst time
                                      // exceeds witness_after
  double time_locked = 0;             // reachable states from which no tick can come
  double zero_time_forever = 0;       // ... from which zero-time steps can go on for ever
  std::vector<Word> time_lock_start;  // a start state that reaches one of either
  bool stopped = false;               // out of time: the figures are not complete
};

// `start` and `legal` are sets of `system`'s space; the system's settled states (set_settled)
// count as in L and are not expanded, as check_stabilisation's `settled` are. A stop the system was
// given (set_stop) ends it with `stopped`. Timed automata only (time is counted in ticks):
// std::invalid_argument otherwise.
StabilisationResult stabilise(const System& system, const bdd& start, const bdd& legal,
                              std::uint64_t witness_after);

} // namespace checker::symbolic
