#pragma once
// The client node CN(δ)_p (seed 000 §5.3, lines 818–850), reconstructed from the text and
// the conference figure (seed 001 Fig. 2, seed 002 Fig. 5); decisions D1–D5 of
// models/vlayer_mc/README.md.
//
//   clock    ⊥ (initially) or the phase of the robot's clock, 0..δ−1 (D15)
//   x        x_p: ⊥ or the robot's lattice point (dead reckoning between GPSupdates)
//   target   x*_p: ⊥ or the target point
//   v        v_p: ⊥, 0 (stored −1) or the point steered to (D4)
//   since    0/1 clock: 0 = the cn-update of this instant was sent (D3)
//
//   input  GPSupdate(l, t)_p          eff x := l; clock := t
//   output vcast(⟨cn-update, p, l⟩)_p pre clock = 0 ∧ since ≥ 1 ∧ x ≠ ⊥ ∧ l = x
//                                     eff since := 0; target := ⊥     (lines 825–827)
//   input  vrcv(⟨target-update, u, t⟩)_p   eff target := t            (001 Fig. 2 line 30)
//   output velocity(w)_p              pre w = desired ≠ v   eff v := w  (D5, lines 836–841)
//   trajectories: clock := clock + 1 mod δ; x steps towards v (D8);
//   stop when the cn-update is due, or v ≠ desired (§5.3 lines 845–850)

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

tioa::Automaton cn(const VlConfig& config, int p);

} // namespace vlayer_mc
