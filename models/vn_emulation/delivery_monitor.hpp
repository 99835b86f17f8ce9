#pragma once
// Theorem 2's d_v for VN messages to the clients (VN -> CN; docs/design/vn-emulation.md
// §3.2 and P5), in ghost variables (DeliverySlots, with EmuConfig::delivery_monitor).
//
// VLBcast's obligation (D29, 002:85): a message VN_h sends reaches every CN in B_h within
// d_v, if that CN is alive for the whole interval. As built:
//  - the abstract send of a VN message is its first physical transmission by any replica
//    (D17); the CNs it is owed to are those of the PNs up then (in one zone every PN is in
//    B_0; a PN that is down is not alive throughout);
//  - a later transmission of the same id by another replica owes nothing new;
//  - a client is paid when its PN receives a packet with that id (the trivial client
//    delivers it once, D16), and let off when its PN fails;
//  - a client message to the VN (Slots::message_wait) is let off when VN_0 restarts
//    (delivery_tobcast), the VN being failed at that step;
//  - two zones: a VN message is owed to the clients in its VN's zone, and to the
//    neighbouring VN if it is alive at the send; that VN is paid at the first execution of
//    the receive by one of its replicas, and lets it off when it is failed at a tick or
//    restarts. A client that leaves the zone is let off;
//  - the wait grows at ticks while something is owed. An id is kept, as sent, until the
//    horizon H after it is paid (D11), so that a late copy is not a new send.

#include "models/vn_emulation/slots.hpp"

namespace vn_emulation {

// send_pn transmits VN message `m` (kind vn_message).
void delivery_transmit(const Slots& slots, State& s, const Packet& m);
// PN_pn receives a packet of VN message `id`.
void delivery_receive(const Slots& slots, State& s, int pn, const Key& id);
// PN_pn fails: it is owed nothing more.
void delivery_fail(const Slots& slots, State& s, int pn);
// PN_pn has moved: a client that left the zone of a VN message is owed it no more.
void delivery_move(const Slots& slots, State& s, int pn);
// A replica executes the receive of VN message `id` (two zones): the neighbouring VN has
// taken it (its first execution).
void delivery_vn_executed(const Slots& slots, State& s, const Key& id);
// TOBcast-rcv_pn delivers `entry`. VN_0 restarts at a reset's first delivery to any PN
// (the map of refinement.hpp): a restart of a live VN is fail_0 then recover_0 (002:83,
// F4), so the client messages sent before it are owed nothing more ("alive for the whole
// interval" no longer holds).
void delivery_tobcast(const Slots& slots, State& s, int pn, const Entry& entry);
// At a tick: the waits of what is owed grow, then the ids age and old paid ones go.
void delivery_tick(const Slots& slots, State& s);
// The longest wait of a VN message still owed to some client (0 when none).
int vn_to_cn_wait(const Slots& slots, const State& s);
// The longest wait of a VN message still owed to the neighbouring VN (two zones).
int vn_to_vn_wait(const Slots& slots, const State& s);

} // namespace vn_emulation
