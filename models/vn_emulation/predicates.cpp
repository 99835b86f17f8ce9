#include "models/vn_emulation/predicates.hpp"

#include "models/vn_emulation/vn_steps.hpp"

namespace vn_emulation {

namespace {

// A join-ack that PN_j, listening with join-id `join_age`, adopts when it is delivered.
bool adoptable(const Packet& p, int join_age) {
  return p.kind == Kind::join_ack && join_age >= 0 && p.age <= join_age;
}

} // namespace

int point_zone(const Slots& slots, const State& s, int i) {
  const PnSlots& p = slots.pns[i];
  return p.point ? EmuConfig::zone_of(s[*p.point]) : 0;
}

bool in_zone(const Slots& slots, const State& s, int i) {
  const PnSlots& p = slots.pns[i];
  return s[p.up] && !s.is_bottom(p.zone) && s[p.zone] == point_zone(slots, s, i);
}

int vne_zone(const Slots& slots, const State& s, int i) {
  return in_zone(slots, s, i) ? static_cast<int>(s[slots.pns[i].zone]) : -1;
}

bool pn_urgent(const Slots& slots, const State& s, int i) {
  const PnSlots& p = slots.pns[i];
  const EmuConfig& c = slots.config;
  if (!s[p.up])
    return false;
  if (s.is_bottom(p.zone) || s[p.zone] != point_zone(slots, s, i)) // zone-update: x ∉ B_h
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
    if ((c.printed_init_action || !s[p.proposed]) && p.value.can_send(s)) // init-action(send)
      return true;
    if (s[p.pending[0].kind] != static_cast<int>(Kind::none)) // simulate-action
      return true;
    const int pending_join = optional_value(s, p.pending_join);
    if (later_id(pending_join, optional_value(s, p.completed_join)) &&
        (!c.quiescent_ack || !p.value.can_send(s))) // ack-join
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
          s[f.oblig ? *f.oblig : f.todo] != 0) // LBcast's deadline for the obliged
        return true;
  }
  return false;
}

namespace {

// The payload of a join-ack that a listening replica of zone h will adopt, if any.
std::optional<VnValue> adoptable_payload(const Slots& slots, const State& s, int h) {
  const int n = slots.config.pns;
  for (int j = 0; j < n; ++j) {
    const PnSlots& p = slots.pns[j];
    if (vne_zone(slots, s, j) != h || s[p.status] != Status::listening)
      continue;
    const int join_age = optional_value(s, p.join_id);
    for (const BufferSlots& b : p.buffer) {
      const Packet packet = b.packet.load(s);
      if (adoptable(packet, join_age))
        return vn_from_payload(slots, packet.value);
    }
    for (int i = 0; i < n; ++i)
      for (const FlightSlots& f : slots.pns[i].flight) {
        if (!((s[f.todo] >> j) & 1))
          continue;
        const Packet packet = f.packet.load(s);
        if (packet.zone == h && adoptable(packet, join_age)) // (TOBcast_j keeps only zone h's)
          return vn_from_payload(slots, packet.value);
      }
  }
  return std::nullopt;
}

} // namespace

std::optional<VnValue> abstract_value(const Slots& slots, const State& s, int h) {
  for (int i = 0; i < slots.config.pns; ++i)
    if (vne_zone(slots, s, i) == h && s[slots.pns[i].status] == Status::active)
      return slots.pns[i].value.load(s);
  return adoptable_payload(slots, s, h);
}

bool vn_alive(const Slots& slots, const State& s, int h) {
  return abstract_value(slots, s, h).has_value();
}

std::optional<std::string> replica_failure(const Slots& slots, const State& s) {
  if (urgent(slots, s))
    return std::nullopt;
  std::optional<int> first[2];
  for (int i = 0; i < slots.config.pns; ++i) {
    const PnSlots& p = slots.pns[i];
    const int h = vne_zone(slots, s, i);
    if (h < 0 || s[p.status] != Status::active)
      continue;
    if (s[p.pending[0].kind] != static_cast<int>(Kind::none))
      return "PN_" + std::to_string(i) + " is active with actions pending where time passes";
    if (!first[h]) {
      first[h] = i;
      continue;
    }
    const VnValue a = slots.pns[*first[h]].value.load(s), b = p.value.load(s);
    if (a != b)
      return "the active replicas PN_" + std::to_string(*first[h]) + " and PN_" +
             std::to_string(i) + " hold different VN states where time passes: (" +
             describe(slots, a) + ") and (" + describe(slots, b) + ")";
  }
  return std::nullopt;
}

} // namespace vn_emulation
