#pragma once
// The real-world automaton RW (seed 000 §4.1, lines 544–566), discretised
// (models/vlayer_mc/README.md D4, D8, D15):
//
//   now            phase of real time, 0..δ−1 (D15), initially 0
//   loc[p]         robot p's lattice point, arbitrary at start
//   vel[p]         ⊥ (initially), 0 (stored −1) or the point p steers to (D4)
//   gps_age[p]     quanta since the last GPSupdate_p (cap ε_sample), initially ε_sample:
//                  the first update is due at time 0
//
//   output GPSupdate(l, t)_p   pre l = loc[p] ∧ t = now ∧ gps_age[p] ≥ 1   eff gps_age[p] := 0
//   input  velocity(v)_p       eff vel[p] := v
//   trajectories: now := now + 1 mod δ; loc[p] steps towards vel[p] (D8);
//                 stop when some gps_age[p] = ε_sample (an update every ε_sample at most)

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

inline constexpr int zero_velocity = -1; // vel[p] = 0, v_p = 0

tioa::Automaton rw(const VlConfig& config);

} // namespace vlayer_mc
