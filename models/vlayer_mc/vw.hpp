#pragma once
// The virtual-world automaton VW (seed 000 §4.1, lines 567–584), discretised (D13, D15):
//
//   now        phase of real time, 0..δ−1, initially 0
//   age[u]     quanta since the last time(t)_u (cap ε_sample), initially ε_sample: "one
//              such update occurs at time 0, and they are repeated at least every
//              ε_sample time thereafter"
//
//   output time(t)_u       pre t = now ∧ age[u] ≥ 1    eff age[u] := 0
//   output fail_u, restart_u   enabled only when vsa_faults (D13); no effect on VW
//   trajectories: now := now + 1 mod δ; ages advance; stop when some age[u] = ε_sample

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

tioa::Automaton vw(const VlConfig& config, bool vsa_faults);

} // namespace vlayer_mc
