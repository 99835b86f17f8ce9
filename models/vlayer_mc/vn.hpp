#pragma once
// The virtual node VN(k, ρ1, ρ2)_u (seed 000 §5.4, lines 852–965), reconstructed from the
// text, Def 7.1(2), §6 line 1011 and the conference figure (seed 002 Fig. 6); decisions
// D1–D3, D6, D7 of models/vlayer_mc/README.md.
//
//   clock    clock_u: ⊥ (initially) or the phase 0..δ−1 (D15)
//   M[p]     M_u: ⊥ (p ∉ dom M) or the point p reported
//   V[i]     V_u(nbrs(u)[i]): the count of its last vn-update (D2), initially 0
//   out[p]   the send buffer: ⊥ or the target-update ⟨p, x*⟩ still to vcast
//   since    0/1 clock: 0 = a timed step happened at this instant (D3)
//
//   input  time(t)_u                     eff clock := t                          (§4.1)
//   input  vrcv(⟨cn-update, p, l⟩)_u     eff if clock ≠ ⊥ ∧ region(l) = u: M[p] := l
//                                                                    (Fig. 6 line 28, D16)
//   input  vrcv(⟨vn-update, g, n⟩)_u     eff if g ∈ nbrs(u): V[g] := n           (Fig. 6 line 42)
//   output vcast(⟨vn-update, u, n⟩)_u    pre clock = e + d + ε ∧ since ≥ 1 ∧ n = |M|
//                                        eff since := 0                          (D1, lines
//                                        868–872)
//   internal compute                     pre clock = e + 2d + 2ε ∧ since ≥ 1
//                                        eff out := calctarget(assign(...)); M := ∅; V := 0;
//                                            since := 0                          (lines 876–884,
//                                            D2)
//   output vcast(⟨target-update, p, x⟩)_u   pre out[p] = x   eff out[p] := ⊥     (D6)
//   trajectories: clock := clock + 1 mod δ; stop when a timed step is due or out ≠ ∅

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

tioa::Automaton vn(const VlConfig& config, RegionId u);

} // namespace vlayer_mc
