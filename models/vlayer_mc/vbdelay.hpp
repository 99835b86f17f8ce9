#pragma once
// VBDelay_p, the buffer of client p (seed 000 §4.1, lines 623–633): it takes vcast(m)_p
// from CN_p and hands m to VBcast as vcast′(m)_p after at most e. The one message of CN_p
// is the cn-update ⟨p, l⟩ (D9: one slot; a second vcast replaces the held message).
//
//   held, age (cap max(e, 1)), loc    (to_send_p^− and to_send_p^+ of Def 7.2(2))
//
//   input  vcast(⟨cn-update, p, l⟩)_p    eff held := true; age := 0; loc := l
//   output vcast′(⟨cn-update, p, l⟩)_p   pre held ∧ l = loc    eff held := false; age := 0
//   trajectories: age advances while held; stop when held ∧ age ≥ e
//
// With junk slots (D31, config.junk > 0: the automata of U(VLNodes) only), slot j holds a
// message ⟨kind, id, value⟩ of models/vlayer_mc/junk.hpp that no vcast put there:
//
//   junk_kind/id/value/age[j]
//   output vcast′_junk(j, kind, id, value)_p  pre slot j holds it   eff slot j := empty
//   trajectories: a full slot's age advances; stop when one is e old
//
// VSAs have e = 0 and no buffer (D7).

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

tioa::Automaton vbdelay(const VlConfig& config, int p);

} // namespace vlayer_mc
