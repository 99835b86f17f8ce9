#pragma once
// The state of the one-zone emulation, variable by variable (docs/design/vn-emulation.md
// §1.3–1.6; README "State"), with value types to read and write its records whole.
//
// Every timestamp is kept as an age (now − ts), saturating at EmuConfig::age_cap() (D23):
// there is no absolute time in the state. An optional value is -1 for ⊥ in the value
// types.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "models/vn_emulation/config.hpp"
#include "models/vn_emulation/vn_counter.hpp"
#include "tioa/automaton.hpp"
#include "tioa/fixed_list.hpp"

namespace vn_emulation {

using tioa::State;
using tioa::Variable;

// What a TOBcast message, a pending action or a physical packet is (D15).
enum class Kind {
  none,             // an empty place
  simulate_receive, // ⟨simulate, ⟨receive, m⟩, ⊥⟩, m the client message `message` of `from`
  simulate_send,    // ⟨simulate, ⟨send, ⟨count, last⟩⟩, oid = ⟨age, from⟩⟩
  join_req,         // ⟨join-req, ⊥, join-id = age⟩
  join_ack,         // ⟨join-ack, ⟨val, completed-actions⟩, id = age⟩
  reset,            // ⟨reset⟩
  client_message,   // a CN's virtual message ⟨vmsg, cn from, id = message⟩ (not TOBcast)
  vn_message // VN_h's virtual message ⟨vmsg, vn h, id = ⟨age, from⟩, ⟨count, last⟩⟩
};
constexpr int kinds = 8;
inline bool through_tobcast(Kind k) {
  return k != Kind::none && k != Kind::client_message && k != Kind::vn_message;
}

// A send key of completed-actions: the oid ⟨age, proposer⟩ of a simulated send (receive
// keys are the client messages' ids, a bit each: they are never reused, so they need no
// age, D10).
struct Key {
  int age = -1, from = 0;
  bool operator==(const Key&) const = default;
};
using Keys = std::array<Key, EmuConfig::key_capacity>;

// completed-actions (D3).
struct Completed {
  int received = 0; // bit c: the receive of client message c
  Keys sends{};
  bool operator==(const Completed&) const = default;
  bool has(const Key& k) const;
  // Adds k; false when there is no room (the model's bound).
  bool add(const Key& k);
};

// A join-ack's payload val as whole numbers (vn_steps.hpp): the counter's code, or the MC
// VN's fields and its sseq.
using Payload = std::array<int, max_mc_fields + 1>;

struct Packet {
  Kind kind = Kind::none;
  int message = 0, from = 0, count = 0, last = 0;
  // The zone of a TOBcast message (the sender VNE's h when it was queued, D12(a)), of a
  // client message (its CN's zone at the send) or of a VN message (its VN's). Always 0
  // with one zone.
  int zone = 0;
  int age = -1;    // the oid's or id's age; -1 when it has none
  Payload value{}; // join-ack: the payload's val (vn_payload)
  Completed done;  // join-ack: the payload's completed-actions
  bool operator==(const Packet&) const = default;
  bool empty() const { return kind == Kind::none; }
};

struct PacketSlots {
  Variable<int> kind, message, from, count, last, age, zone;
  // Only where join-acks can be (TOBcast-out, LBcast, TOBcast's buffer).
  bool payload = false;
  std::vector<Variable<int>> value; // Payload's numbers (⊥ is -1, a value of the range)
  Variable<int> received;
  std::array<Variable<int>, EmuConfig::key_capacity> key_age, key_from;

  Packet load(const State& s) const;
  void store(State& s, const Packet& p) const;
};

// An LBcast packet in flight from one sender (002:37): its age since the send (0..d_p),
// the PNs that may still receive it, and, for TOBcast packets, the sender's sequence
// number in that instant (the timestamp is the send time, so the age, D12).
struct FlightSlots {
  PacketSlots packet;
  Variable<int> age, todo, sequence;
  // Two zones: the PNs that must still receive it (in todo, up and within R_p of the
  // sender throughout, D28); with one zone everybody in todo must.
  std::optional<Variable<int>> oblig;
};

// An entry of TOBcast_i's hold buffer: ⟨ts, jr, sender, seq, m⟩ (D12).
struct BufferSlots {
  PacketSlots packet;
  Variable<int> age, sender, sequence;
};

struct Entry {
  Packet packet;
  int age = 0, sender = 0, sequence = 0;
};
// TOBcast's order of delivery (002:348): an older timestamp (a larger age) first, join-reqs
// after the other messages of their timestamp, then sender and sequence number.
inline auto tag_order(const Entry& e) {
  return std::make_tuple(-e.age, e.packet.kind == Kind::join_req, e.sender, e.sequence);
}
// A packet's content as one sortable value, to order two messages with one tag (E4).
using ContentOrder = std::pair<std::array<int, 8 + 2 * EmuConfig::key_capacity>, Payload>;
ContentOrder content_order(const Packet& p);
// x before y in TOBcast's order; two entries with one tag by their content when
// `by_content`, else neither before the other.
inline bool delivered_before(const Entry& x, const Entry& y, bool by_content) {
  if (tag_order(x) != tag_order(y) || !by_content)
    return tag_order(x) < tag_order(y);
  return content_order(x.packet) < content_order(y.packet);
}
// A TOBcast buffer's entries (or P7's taken messages), loaded whole.
using Entries = tioa::FixedList<Entry, EmuConfig::max_buffer_capacity>;

// VN_h's state as a replica holds it: the counter's variables, or with vn=mc the MC VN's
// (McContext::fields(), in `mc`) and sseq.
struct ValueSlots {
  Variable<int> count, last, length, sseq;
  std::array<Variable<int>, EmuConfig::out_capacity> out_count, out_last;
  std::optional<Variable<int>> nbr; // two zones
  std::vector<Variable<int>> mc;
  std::optional<Variable<int>> head_kind; // mc's buffer[0].kind
  const McContext* mc_context = nullptr;  // vn=mc (owned by Slots::mc)
  VnValue load(const State& s) const;
  void store(State& s, const VnValue& v) const;
  // The VN has a send to make (δ(val, ⟨send, m⟩) ≠ ⊥ for some m), read in place.
  bool can_send(const State& s) const;
};

enum class Status { idle, joining, listening, active }; // D1: idle is used, not declared

// Which of the model's bounds a step met (EmuConfig): the state is a dead end there.
enum class Bound {
  none,
  pending,
  tob_out,
  local_out,
  flight,
  buffer,
  keys,
  seen,
  sequence,
  out,
  sent_ids,
  taken,
  delivery_ids
};
const char* to_string(Bound bound);

// A block of contiguous bits of the state, for footprints.
struct Block {
  std::uint32_t offset = 0, bits = 0;
};

// PN_i = CN_i ‖ VNE_i ‖ TOBcast_i (D41), and the LBcast packets it sent.
struct PnSlots {
  Variable<bool> up;                                   // mode active (002:35)
  Variable<Status> status;                             // 002:405
  Variable<int> zone;                                  // h ∈ H ∪ {⊥}; one zone: 0 or ⊥
  ValueSlots value;                                    // val
  Variable<int> pending_join, completed_join, join_id; // ages, ⊥ below every id (D21)
  Variable<bool> reset_sent, proposed;                 // D7, D6
  Variable<int> received;                              // completed-actions: receive keys (bits)
  std::array<Variable<int>, EmuConfig::key_capacity> key_age, key_from; // send keys
  std::vector<PacketSlots> pending;                                     // pending-actions
  std::vector<PacketSlots> tob_out;                                     // TOBcast-out
  std::vector<PacketSlots> local_out; // local-out (VN messages to transmit)
  Variable<int> sequence;             // TOBcast_i's next sequence number (D12c)
  std::vector<BufferSlots> buffer;    // TOBcast_i's held packets, in delivery order
  std::vector<FlightSlots> flight;    // LBcast: this PN's packets in flight
  std::array<Variable<int>, EmuConfig::seen_capacity> seen_age, seen_from; // CN_i (D16)
  Variable<bool> sent_now; // CN_i has sent in this instant (§1.6)
  // vn=mc: how many of its round's three messages CN_i has sent (M1, M7).
  std::optional<Variable<int>> cn_phase;
  // Theorem 2's monitors (ghosts, §3.2): quanta PN_i has stood in a zone whose VN is failed.
  Variable<int> startup_wait;
  // The model's bound that one of this PN's steps met (Bound::none: none). Kept per PN so
  // that a step reads only its own PN's (for the zero-time reduction); any one set makes
  // the state a dead end of the model (Slots::past_bound).
  Variable<Bound> bound_met;
  // Two zones: the lattice point PN_i stands at (RW's x_i, D27), and the quanta before it
  // may step again.
  std::optional<Variable<int>> point, move_wait;
  Block block;        // every variable above but the flight
  Block flight_block; // the flight
};

// The ghosts of P7's monitor (refinement.hpp; docs/design/vn-emulation.md §1.8, §4.3):
// the abstract VN_0 run on the events the emulation maps to its actions.
struct RefinementSlots {
  // A reference replica: it takes each TOBcast message once, at its first delivery to a
  // replica, and executes it at once, as a VNE would (refinement.hpp).
  ValueSlots abstract;         // val_abs, VN_0's state as the abstract VN holds it
  Variable<int> done_received; // its completed receives
  std::array<Variable<int>, EmuConfig::key_capacity> done_age, done_from; // completed sends
  // The TOBcast messages it has taken in this instant (a message's tag ⟨ts, sender,
  // sequence⟩ and its content without a join-ack's payload: a PN that fails and recovers
  // within an instant starts its sequence numbers again, so a tag alone may repeat).
  std::vector<BufferSlots> taken;
  // The ids of the VN messages it has sent (D10), kept across restarts; a transmission of
  // any other is refused. Collected after the horizon (D11), as the others.
  std::array<Variable<int>, EmuConfig::sent_capacity> sent_age, sent_from;
  // The first refused transmission: 0 none, else 1 + the transmitting PN.
  Variable<int> refused_by;
  // P6: VN_0 was alive at the last tick, and a reset was delivered while it still was (a
  // restart of a live VN, F4).
  Variable<bool> was_alive, live_restart;
  Block block;
};

// The ghosts of Theorem 2's d_v for VN messages to the clients (VN -> CN, §3.2 and P5 of
// docs/design/vn-emulation.md; delivery_monitor.hpp): each VN message id from its first
// transmission on (the abstract send, D17), the clients it is still owed to, and the
// quanta since (⊥ once nothing is owed). Sorted by id, the empty places last.
struct DeliverySlots {
  std::array<Variable<int>, EmuConfig::sent_capacity> age, from, owed, wait;
  // Two zones: each message's VN, and the quanta it has been owed to the neighbouring VN
  // (bit `pns` of owed; ⊥ when not owed). Empty with one zone.
  std::vector<Variable<int>> zone, vn_wait;
  // The resets delivered in this instant, by their TOBcast tag ⟨sender, sequence⟩ (+1; 0
  // for an empty place): VN_0 restarts at a reset's first delivery to any PN.
  std::vector<Variable<int>> reset_tag;
  Block block;
};

struct Slots {
  EmuConfig config;
  std::shared_ptr<const McContext> mc; // the MC VN's δ, with vn=mc
  std::vector<PnSlots> pns;
  Variable<int> messages_left, fails_left;
  std::optional<Variable<int>> moves_left; // two zones
  // Monitors: per zone, the VN's send task (quanta enabled without a send, and the send
  // count it saw at the last tick); per client message, quanta since its send while the
  // VN of its zone owed it (and, with two zones, that zone).
  std::vector<Variable<int>> task_wait, task_sseq;
  std::vector<Variable<int>> message_wait, message_zone;
  std::vector<RefinementSlots> refinement; // with EmuConfig::refinement_monitor: a zone each
  std::optional<DeliverySlots> delivery;   // with EmuConfig::delivery_monitor
  // The first bit of the ghosts a check declares for itself (refinement, delivery): a
  // trace cut there replays on the emulation without them.
  std::uint32_t check_ghosts = 0;

  Completed completed(const State& s, int pn) const;
  void set_completed(State& s, int pn, const Completed& c) const;
  Entry entry(const State& s, const BufferSlots& b) const;
  // Some step met one of the model's bounds: the state stands for continuations the model
  // cannot hold (no check reads past it).
  bool past_bound(const State& s) const;
  // The first bound met, for reports (Bound::none when none).
  Bound bound_met(const State& s) const;
  bool pn_past_bound(const State& s, int pn) const { return s[pns[pn].bound_met] != Bound::none; }
  // Records that a step of PN_pn met `bound` (the first one met stays).
  void exceed(State& s, int pn, Bound bound) const {
    if (s[pns[pn].bound_met] == Bound::none)
      s[pns[pn].bound_met] = bound;
  }
};

// Stores `entries` in `places`, in that order; the places left over are emptied.
void store_entries(State& s, const std::vector<BufferSlots>& places, const Entries& entries);

// Declares every variable of the emulation in `a`.
std::shared_ptr<const Slots> declare(tioa::Automaton& a, const EmuConfig& config);

// Small helpers for optional integers (-1 for ⊥).
inline int optional_value(const State& s, const Variable<int>& v) {
  return s.is_bottom(v) ? -1 : static_cast<int>(s[v]);
}
inline void set_optional(State& s, const Variable<int>& v, int value) {
  if (value < 0)
    s.set_bottom(v);
  else
    s[v] = value;
}

} // namespace vn_emulation
