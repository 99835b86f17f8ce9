#include "models/vn_emulation/predicates.hpp"

namespace vn_emulation {

namespace {

// A join-ack that PN_j, listening with join-id `join_age`, adopts when it is delivered.
bool adoptable(const Packet& p, int join_age) {
  return p.kind == Kind::join_ack && join_age >= 0 && p.age <= join_age;
}

} // namespace

bool in_zone(const Slots& slots, const State& s, int i) {
  const PnSlots& p = slots.pns[i];
  return s[p.up] && !s.is_bottom(p.zone);
}

bool pn_urgent(const Slots& slots, const State& s, int i) {
  const PnSlots& p = slots.pns[i];
  const EmuConfig& c = slots.config;
  if (!s[p.up])
    return false;
  if (s.is_bottom(p.zone)) // zone-update: x ∉ B_⊥
    return true;
  const Status status = s[p.status];
  if (status == Status::idle) // join
    return true;
  // restart and init-action: as printed (F1), their preconditions do not read reset-sent
  // and proposed, so time stays stopped after they fire (emulation.cpp, "restart").
  if (status == Status::listening && (c.printed_restart || !s[p.reset_sent]) &&
      optional_value(s, p.join_id) == c.restart_age()) // restart
    return true;
  if (status == Status::active) {
    if ((c.printed_init_action || !s[p.proposed]) && s[p.value.length] > 0) // init-action(send)
      return true;
    if (s[p.pending[0].kind] != static_cast<int>(Kind::none)) // simulate-action
      return true;
    const int pending_join = optional_value(s, p.pending_join);
    if (later_id(pending_join, optional_value(s, p.completed_join)) &&
        (!c.quiescent_ack || s[p.value.length] == 0)) // ack-join
      return true;
  }
  if (s[p.tob_out[0].kind] != static_cast<int>(Kind::none)) // TOBcast(m)
    return true;
  if (s[p.local_out[0].kind] != static_cast<int>(Kind::none)) // send(m)
    return true;
  if (s[p.buffer[0].packet.kind] != static_cast<int>(Kind::none) &&
      optional_value(s, p.buffer[0].age) >= c.hold()) // TOBcast-rcv
    return true;
  return false;
}

bool urgent(const Slots& slots, const State& s) {
  for (int i = 0; i < slots.config.pns; ++i) {
    if (pn_urgent(slots, s, i))
      return true;
    for (const FlightSlots& f : slots.pns[i].flight)
      if (s[f.packet.kind] != static_cast<int>(Kind::none) && s[f.age] == slots.config.d_p &&
          s[f.todo] != 0)
        return true;
  }
  return false;
}

namespace {

// The payload of a join-ack that a listening replica will adopt, if any.
std::optional<VnValue> adoptable_payload(const Slots& slots, const State& s) {
  const int n = slots.config.pns;
  for (int j = 0; j < n; ++j) {
    const PnSlots& p = slots.pns[j];
    if (!in_zone(slots, s, j) || s[p.status] != Status::listening)
      continue;
    const int join_age = optional_value(s, p.join_id);
    for (const BufferSlots& b : p.buffer) {
      const Packet packet = b.packet.load(s);
      if (adoptable(packet, join_age))
        return VnValue::from_code(packet.value, n);
    }
    for (int i = 0; i < n; ++i)
      for (const FlightSlots& f : slots.pns[i].flight) {
        if (!((s[f.todo] >> j) & 1))
          continue;
        const Packet packet = f.packet.load(s);
        if (adoptable(packet, join_age))
          return VnValue::from_code(packet.value, n);
      }
  }
  return std::nullopt;
}

} // namespace

std::optional<VnValue> abstract_value(const Slots& slots, const State& s) {
  for (int i = 0; i < slots.config.pns; ++i)
    if (in_zone(slots, s, i) && s[slots.pns[i].status] == Status::active)
      return slots.pns[i].value.load(s);
  return adoptable_payload(slots, s);
}

bool vn_alive(const Slots& slots, const State& s) {
  return abstract_value(slots, s).has_value();
}

std::string describe(const VnValue& v) {
  std::string out;
  for (int k = 0; k < v.length; ++k)
    out += (k ? ", " : "") + std::string("<") + std::to_string(v.out_count[k]) + ", CN_" +
           std::to_string(v.out_last[k]) + ">";
  return "count " + std::to_string(v.count) + ", last " +
         (v.last < 0 ? std::string("⊥") : "CN_" + std::to_string(v.last)) + ", out [" + out +
         "], sseq " + std::to_string(v.sseq);
}

std::optional<std::string> replica_failure(const Slots& slots, const State& s) {
  if (urgent(slots, s))
    return std::nullopt;
  std::optional<int> first;
  for (int i = 0; i < slots.config.pns; ++i) {
    const PnSlots& p = slots.pns[i];
    if (!in_zone(slots, s, i) || s[p.status] != Status::active)
      continue;
    if (s[p.pending[0].kind] != static_cast<int>(Kind::none))
      return "PN_" + std::to_string(i) + " is active with actions pending where time passes";
    if (!first) {
      first = i;
      continue;
    }
    const VnValue a = slots.pns[*first].value.load(s), b = p.value.load(s);
    if (a != b)
      return "the active replicas PN_" + std::to_string(*first) + " and PN_" + std::to_string(i) +
             " hold different VN states where time passes: (" + describe(a) + ") and (" +
             describe(b) + ")";
  }
  return std::nullopt;
}

} // namespace vn_emulation
