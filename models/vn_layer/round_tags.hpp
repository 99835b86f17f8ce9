#pragma once
// Round numbers in a finite state (docs/design/vn-layer.md C23). The layer's messages and
// its VN carry round numbers (N in Figs. 2–3); the model keeps each as its age relative to
// the current round ⌊realtime/δ⌋: 0 this round, 1 the previous one, 2 older. Every
// comparison the figures make is between a trigger's round and a stored one, and a
// trigger is at most one round old when it is delivered (config.cpp: the target-trigger
// phase lies inside the round, and d_v < δ), so ages decide them exactly. Each component
// that holds tags keeps its own copy of the phase (realtime mod δ) and ages its tags when
// the phase wraps: composition shares actions, not variables (C21).

#include <algorithm>

#include "tioa/automaton.hpp"

namespace vn_layer {

inline constexpr int this_round = 0, last_round = 1, older_round = 2;

inline int aged(int tag) {
  return std::min(tag + 1, older_round);
}

// realtime mod δ, and ⌊realtime/δ⌋ saturating at 2: the age of round 0, which is the
// initial round number of vn-done, target-done and V (Fig. 3 lines 14–20).
struct RoundClock {
  tioa::Variable<int> phase;
  tioa::Variable<int> epoch;
  int delta;

  RoundClock(tioa::Automaton& a, int delta)
      : phase(a.integer("phase", 0, delta - 1, 0)), epoch(a.integer("epoch", 0, older_round, 0)),
        delta(delta) {}

  // One quantum; true when a round begins.
  bool tick(tioa::State& s) const {
    s[phase] = (s[phase] + 1) % delta;
    if (s[phase] != 0)
      return false;
    s[epoch] = aged(s[epoch]);
    return true;
  }
  int round_zero(const tioa::State& s) const { return s[epoch]; }
};

} // namespace vn_layer
