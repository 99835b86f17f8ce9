#pragma once
// The VN emulation of seed 002 §VIII on one zone (docs/design/vn-emulation.md, instance
// I1; README.md): PN_0..PN_{n−1}, each CN_i ‖ VNE_i ‖ TOBcast_i (Fig. 10, D41), over one
// LBcast(R_p, d_p) in which every PN of the zone is in range of every other, emulating
// VN_0, a FIFO counter (vn_counter.hpp). The environment sends `messages` client messages
// and fails PNs `fails` times in all (a failed PN may recover at any time).
//
// The automaton is one, not a composition: a PN's components share x_i and fail together
// (D41), and the synchronised steps a composition would make (TOBcast(m)_{i,h} with
// TOBcast_i's send, lb-send with LBcast's input) are one step each here, as they would
// be there. Its actions keep the figure's names with the PN's id: join_0,
// simulate-action_1, TOBcast-rcv_0, lb-rcv_1(from, slot), ...

#include <memory>

#include "models/vn_emulation/slots.hpp"
#include "tioa/automaton.hpp"

namespace vn_emulation {

struct Emulation {
  tioa::Automaton automaton;
  std::shared_ptr<const Slots> slots;
};

Emulation emulation(const EmuConfig& config);

} // namespace vn_emulation
