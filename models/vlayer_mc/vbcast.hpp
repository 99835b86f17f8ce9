#pragma once
// The virtual broadcast service VBcast (seed 000 §4.1, lines 635–651): a message vcast′
// from a sender in region u is delivered, within d, to the clients and VSAs in u and its
// neighbours (D10–D12 of models/vlayer_mc/README.md). vbcastq holds one slot per (sender,
// kind); the pending set P′ keeps only the receivers a delivery has an effect on (D11).
//
//   reg[p]                 Vbcast.reg(p): ⊥ or the region of the last GPSupdate_p (D10)
//   cn_pending/age/loc[p]  ⟨cn-update, p, l⟩ of client p; its receiver is VN_region(l)
//   vn_mask/age/count[u]   ⟨vn-update, u, n⟩; bit i of the mask: nbrs(u)[i] still to get it
//   tu_pending/age/target[u·N + p]   ⟨target-update, p, x*⟩ of VN_u; its receiver is CN_p
//
//   input  GPSupdate(l, t)_p           eff reg[p] := region(l)
//   input  vcast′(⟨cn-update, p, l⟩)_p eff slot := ⟨l⟩, P′ := {VN_region(l)} if
//                                          region(l) ∈ nbrs+(reg[p]), else ∅
//   input  vcast(⟨vn-update, u, n⟩)_u  eff slot := ⟨n⟩, P′ := nbrs(u)
//   input  vcast(⟨target-update, p, x⟩)_u   eff slot := ⟨x⟩, P′ := {p} if reg[p] ∈ nbrs+(u)
//   output vrcv(⟨cn-update, p, l⟩)_v, vrcv(⟨vn-update, u, n⟩)_v, vrcv(⟨target-update, u, x⟩)_p
//                                      pre the receiver is in P′    eff remove it from P′
//   trajectories: the age of a slot with receivers advances; stop when such a slot is d old
//
// With junk slots (D31, config.junk > 0: the automata of U(VLNodes) only), the messages a
// client's VBDelay held at the start are on their way in slot p·junk + j:
//
//   junk_kind/id/value[i]   the message (models/vlayer_mc/junk.hpp)
//   junk_from[i], junk_to[i], junk_age[i]   the sender's region, the mask of receivers still
//                                           to get it (junk::receivers), its age
//   input  vcast′_junk(j, kind, id, value)_p   eff slot := the message, to := its receivers
//                                              from reg[p] (empty when none)
//   the deliveries above also deliver junk copies: one choice per copy pending for the
//   receiver, the sender's own slot first

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

tioa::Automaton vbcast(const VlConfig& config);

} // namespace vlayer_mc
