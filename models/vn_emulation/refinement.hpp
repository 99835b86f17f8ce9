#pragma once
// P7 of docs/design/vn-emulation.md (§1.8, §4.3): the emulation implements the abstract
// VN_0. A deterministic monitor runs the abstract FIFO counter (vn_counter.hpp) on the
// events the emulation maps to VN_0's external actions, in ghost variables
// (RefinementSlots, with EmuConfig::refinement_monitor).
//
// The map, as built: a reference replica. The VNEs are replicas of one state machine fed
// by TOBcast's total order, so the monitor takes each TOBcast message once, at its first
// delivery to a replica (a listening or active VNE), and executes it at once as a VNE
// executes a pending action (002:446–452), with completed-actions of its own:
//  - ⟨simulate, ⟨receive, m⟩⟩: receive(m)_0 unless m is completed;
//  - ⟨simulate, ⟨send, m⟩, oid⟩: send(m)_0 when oid is not completed and δ(val_abs,
//    send(m)) is defined (else skipped, as a VNE skips it); the VN message sent has the id
//    oid (D10), and a physical transmission of a VN message whose id the reference
//    replica did not send is refused (a violation);
//  - ⟨reset⟩ (D5): VN_0 restarts from its start state, nothing completed. While VN_0 is
//    alive this is fail_0 then recover_0 at one step, which seed 002's layer allows
//    (002:83; F4, to be reported as P6), while it is failed recover_0;
//  - fail_0 (VN_0 no longer alive, D18): what the reference replica holds then no longer
//    matters, since only a reset brings VN_0 back; at a tick where VN_0 is failed it is
//    set to the start state, so that a failed VN_0 is one ghost value.
// A joining VNE's deliveries do not count: after a fail its buffer lacks what was in
// flight, so its order is not the replicas'. Two simpler maps were tried and give
// violations that are the map's, not the emulation's (README, "refines-vn"): events at
// the first *execution* by any replica (the specification's §1.8) and at the first
// delivery to any VNE: both order events by the interleaving of replicas within an
// instant, not by TOBcast's order.
//
// With two zones there is one such monitor a zone (RefinementSlots per zone): a TOBcast
// message goes to the monitor of the zone it is tagged with, a VN message to its VN's, and
// a neighbour's report received (simulate_receive with an id) sets the reference
// replica's nbr as it sets a VNE's.
//
// The check: no refused transmission, and wherever time can pass every active replica
// holds val_abs of its zone. With Theorem 2's timing monitors (theorem-2) this is the inclusion of
// the emulation's traces, projected on VN_0's actions, in the abstract VN's.

#include <array>
#include <optional>
#include <string>

#include "models/vn_emulation/slots.hpp"

namespace vn_emulation {

// TOBcast-rcv_pn delivers `entry` (any kind; the monitor takes the TOBcast messages the
// abstract VN reads at their first delivery).
void monitor_delivery(const Slots& slots, State& s, int pn, const Entry& entry);
// send_pn transmits VN message `m` (kind vn_message).
void monitor_transmit(const Slots& slots, State& s, int pn, const Packet& m);
// At a tick, before the ages grow: `alive[h]` is VN_h's liveness where time passes.
void monitor_tick(const Slots& slots, State& s, const std::array<bool, 2>& alive);
// Ages of the monitor's ids grow by one, and old ones go (D11).
void monitor_age(const Slots& slots, State& s);

// P6 (F4): a reset has been delivered while VN_0 was alive, as it was at the last tick
// before (a restart of a live VN; seed 002's layer allows it, seed 000's "VSA V_u is not
// failed", 000:1177–1178, and the layer's vn_fail=empty do not).
bool restarted_live(const Slots& slots, const State& s);

// What breaks P7 in `s`, in words: a refused transmission, or (where time can pass) an
// active replica whose val is not val_abs. nullopt when nothing does.
std::optional<std::string> refinement_failure(const Slots& slots, const State& s);

} // namespace vn_emulation
