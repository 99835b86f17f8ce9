#pragma once
// The emulated VN's δ, for whichever VN an instance emulates: the counter (vn_counter.hpp,
// `vn=fifo` or `report`) or the MC VN (vn_mc.hpp, `vn=mc`). The VNEs, the monitors and the
// checks run the VN through these.

#include <string>
#include <utility>

#include "models/vn_emulation/slots.hpp"

namespace vn_emulation {

// δ(val, ⟨send, m⟩) ≠ ⊥ for some m.
bool vn_can_send(const Slots& slots, const VnValue& v);
// The content ⟨count, last⟩ of that send: the counter's head(out); the MC VN's buffer head
// as one number (McContext::head) and 0.
std::pair<int, int> vn_head(const Slots& slots, const VnValue& v);
bool vn_send_enabled(const Slots& slots, const VnValue& v, int count, int last);
void vn_send(const Slots& slots, VnValue& v);
// receive(m) at VN_h of CN `client`'s message m with its content (a packet's count); false
// when the VN has no room for what it would queue (the model's bound `out`; v unchanged).
bool vn_receive(const Slots& slots, VnValue& v, int h, int client, int content);
// receive(m) of the neighbouring VN's message m (two zones; §1.7, M4).
void vn_receive_neighbour(const Slots& slots, VnValue& v, int content);

// A join-ack's payload and back.
Payload vn_payload(const Slots& slots, const VnValue& v);
VnValue vn_from_payload(const Slots& slots, const Payload& payload);

std::string describe(const Slots& slots, const VnValue& v);

} // namespace vn_emulation
