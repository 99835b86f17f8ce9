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
//
// With the d_r rule (D32, config.dr_rule; seed 000 lines 1176–1178) VW also follows the
// clients:
//
//   client_region[p]  ⊥ or the region of p's last GPSupdate; client_up[p] not failed
//   stay[p]           quanta p has been up in client_region[p] (cap d_r)
//   calm[u]           quanta since a live client failed in u or left it (cap d_r)
//   kept[u]           VW restarted VN_u since C_u began
//   C_u               calm[u] ≥ d_r ∧ some up client p has client_region[p] = u ∧ stay[p] ≥ d_r
//
//   input  GPSupdate(l, t)_p    eff a new region: the old one is disturbed (calm := 0,
//                                   kept := false) if p is up; region := region(l); stay := 0
//   input  fail_CN_p            eff p's region is disturbed if p was up; up := false
//   input  restart_CN_p         eff up := true, stay := 0 if p was failed
//   output fail_u               pre vsa_faults ∧ ¬C_u
//   output restart_u            pre vsa_faults ∨ (C_u ∧ ¬kept[u])   eff kept[u] := C_u
//   trajectories: stay of up clients and calm advance; stop when C_u ∧ ¬kept[u]

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

tioa::Automaton vw(const VlConfig& config, bool vsa_faults);

} // namespace vlayer_mc
