#include "models/vn_emulation/slots.hpp"

#include <algorithm>
#include <string>

namespace vn_emulation {

namespace {

std::string at(const std::string& name, int index) {
  return name + "[" + std::to_string(index) + "]";
}

// Ages of timestamps: 0..cap, ⊥ for none (D23).
Variable<int> age_variable(tioa::Automaton& a, const std::string& name, const EmuConfig& c) {
  return a.optional_integer(name, 0, c.age_cap());
}

// The MC VN's fields under `name` (McContext::fields()).
std::vector<Variable<int>> mc_variables(tioa::Automaton& a, const std::string& name,
                                        const McContext& mc) {
  std::vector<Variable<int>> out;
  for (const McField& f : mc.fields())
    out.push_back(f.optional ? a.optional_integer(name + "." + f.name, f.lo, f.hi)
                             : a.integer(name + "." + f.name, f.lo, f.hi, 0));
  return out;
}

PacketSlots packet_slots(tioa::Automaton& a, const std::string& name, const EmuConfig& c,
                         const McContext* mc, bool payload) {
  const int clients = c.pns;
  PacketSlots p;
  p.kind = a.integer(name + ".kind", 0, kinds - 1, 0);
  p.message = a.integer(name + ".message", 0, std::max(c.messages - 1, 0), 0);
  p.from = a.integer(name + ".from", 0, clients - 1, 0);
  // The content: the counter's ⟨count, last⟩, or with vn=mc one number in count (a client
  // message's or the VN's, McContext::contents()) and last 0.
  p.count =
      a.integer(name + ".count", 0, mc ? mc->contents() - 1 : EmuConfig::counter_modulus - 1, 0);
  p.last = a.integer(name + ".last", 0, clients - 1, 0);
  p.age = age_variable(a, name + ".age", c);
  p.zone = a.integer(name + ".zone", 0, c.zones - 1, 0);
  p.payload = payload;
  if (payload) {
    if (mc) { // a join-ack carries the fields themselves: their code does not fit a number
      // ⊥ is -1 here, not an optional value, so that a packet with no payload (all 0) is
      // the declared start value: one state for one situation.
      for (const McField& f : mc->fields())
        p.value.push_back(a.integer(name + ".val." + f.name, f.optional ? -1 : f.lo, f.hi, 0));
      p.value.push_back(a.integer(name + ".val.sseq", 0, EmuConfig::send_modulus - 1, 0));
    } else {
      p.value.push_back(a.integer(name + ".val", 0, VnValue::codes(clients, c.zones) - 1, 0));
    }
    p.received = a.integer(name + ".completed", 0, (1 << c.messages) - 1, 0);
    for (int k = 0; k < EmuConfig::key_capacity; ++k) {
      p.key_age[k] = age_variable(a, at(name + ".key_age", k), c);
      p.key_from[k] = a.integer(at(name + ".key_from", k), 0, clients - 1, 0);
    }
  }
  return p;
}

// A TOBcast entry ⟨ts, sender, seq, m⟩ (a hold buffer's place, or one P7's monitor took).
BufferSlots buffer_slots(tioa::Automaton& a, const std::string& name, const EmuConfig& c,
                         const McContext* mc, bool payload) {
  PacketSlots packet = packet_slots(a, name, c, mc, payload);
  Variable<int> age = age_variable(a, name + ".ts_age", c);
  Variable<int> sender = a.integer(name + ".sender", 0, c.pns - 1, 0);
  return {packet, age, sender, a.integer(name + ".seq", 0, EmuConfig::sequence_capacity, 0)};
}

ValueSlots value_slots(tioa::Automaton& a, const std::string& name, const EmuConfig& c,
                       const McContext* mc) {
  const int clients = c.pns;
  ValueSlots v;
  if (mc) {
    v.mc = mc_variables(a, name, *mc);
    v.mc_context = mc;
    for (std::size_t k = 0; k < mc->fields().size(); ++k)
      if (mc->fields()[k].name == "buffer[0].kind")
        v.head_kind = v.mc[k];
    v.sseq = a.integer(name + ".sseq", 0, EmuConfig::send_modulus - 1, 0);
    return v;
  }
  v.count = a.integer(name + ".count", 0, EmuConfig::counter_modulus - 1, 0);
  v.last = a.optional_integer(name + ".last", 0, clients - 1);
  v.length = a.integer(name + ".out_length", 0, EmuConfig::out_capacity, 0);
  for (int k = 0; k < EmuConfig::out_capacity; ++k) {
    v.out_count[k] = a.integer(at(name + ".out_count", k), 0, EmuConfig::counter_modulus - 1, 0);
    v.out_last[k] = a.integer(at(name + ".out_last", k), 0, clients - 1, 0);
  }
  v.sseq = a.integer(name + ".sseq", 0, EmuConfig::send_modulus - 1, 0);
  if (c.zones == 2)
    v.nbr = a.optional_integer(name + ".nbr", 0, EmuConfig::counter_modulus - 1);
  return v;
}

} // namespace

bool Completed::has(const Key& k) const {
  return std::find(sends.begin(), sends.end(), k) != sends.end();
}

bool Completed::add(const Key& k) {
  if (has(k))
    return true;
  const auto free =
      std::find_if(sends.begin(), sends.end(), [](const Key& e) { return e.age < 0; });
  if (free == sends.end())
    return false;
  *free = k;
  // One order for one set: by age, then proposer, the empty places last.
  std::sort(sends.begin(), sends.end(), [](const Key& x, const Key& y) {
    const int ax = x.age < 0 ? 1 << 20 : x.age, ay = y.age < 0 ? 1 << 20 : y.age;
    return ax != ay ? ax < ay : x.from < y.from;
  });
  return true;
}

Packet PacketSlots::load(const State& s) const {
  Packet p;
  p.kind = static_cast<Kind>(static_cast<int>(s[kind]));
  p.message = s[message];
  p.from = s[from];
  p.count = s[count];
  p.last = s[last];
  p.age = optional_value(s, age);
  p.zone = s[zone];
  if (payload) {
    for (std::size_t k = 0; k < value.size(); ++k)
      p.value[k] = s[value[k]];
    p.done.received = s[received];
    for (int k = 0; k < EmuConfig::key_capacity; ++k)
      p.done.sends[k] = {optional_value(s, key_age[k]), s[key_from[k]]};
  }
  return p;
}

void PacketSlots::store(State& s, const Packet& p) const {
  s[kind] = static_cast<int>(p.kind);
  s[message] = p.message;
  s[from] = p.from;
  s[count] = p.count;
  s[last] = p.last;
  set_optional(s, age, p.age);
  s[zone] = p.zone;
  if (payload) {
    for (std::size_t k = 0; k < value.size(); ++k)
      s[value[k]] = p.value[k];
    s[received] = p.done.received;
    for (int k = 0; k < EmuConfig::key_capacity; ++k) {
      set_optional(s, key_age[k], p.done.sends[k].age);
      s[key_from[k]] = p.done.sends[k].from;
    }
  }
}

VnValue ValueSlots::load(const State& s) const {
  VnValue v;
  if (mc_context) {
    McValues values{};
    for (std::size_t k = 0; k < mc.size(); ++k)
      values[k] =
          mc_context->fields()[k].optional ? optional_value(s, mc[k]) : static_cast<int>(s[mc[k]]);
    v.mc = mc_context->unflatten(values);
    v.sseq = s[sseq];
    return v;
  }
  v.count = s[count];
  v.last = optional_value(s, last);
  v.length = s[length];
  for (int k = 0; k < EmuConfig::out_capacity; ++k) {
    v.out_count[k] = s[out_count[k]];
    v.out_last[k] = s[out_last[k]];
  }
  v.sseq = s[sseq];
  if (nbr)
    v.nbr = optional_value(s, *nbr);
  return v;
}

void ValueSlots::store(State& s, const VnValue& v) const {
  if (mc_context) {
    const McValues values = mc_context->flatten(v.mc);
    for (std::size_t k = 0; k < mc.size(); ++k) {
      if (mc_context->fields()[k].optional)
        set_optional(s, mc[k], values[k]);
      else
        s[mc[k]] = values[k];
    }
    s[sseq] = v.sseq;
    return;
  }
  s[count] = v.count;
  set_optional(s, last, v.last);
  s[length] = v.length;
  for (int k = 0; k < EmuConfig::out_capacity; ++k) {
    s[out_count[k]] = v.out_count[k];
    s[out_last[k]] = v.out_last[k];
  }
  s[sseq] = v.sseq;
  if (nbr)
    set_optional(s, *nbr, v.nbr);
}

bool ValueSlots::can_send(const State& s) const {
  if (mc_context) // the head of the send-buffer
    return s[*head_kind] != static_cast<int>(McSend::none);
  return s[length] > 0;
}

Completed Slots::completed(const State& s, int pn) const {
  const PnSlots& p = pns[pn];
  Completed c;
  c.received = s[p.received];
  for (int k = 0; k < EmuConfig::key_capacity; ++k)
    c.sends[k] = {optional_value(s, p.key_age[k]), s[p.key_from[k]]};
  return c;
}

void Slots::set_completed(State& s, int pn, const Completed& c) const {
  const PnSlots& p = pns[pn];
  s[p.received] = c.received;
  for (int k = 0; k < EmuConfig::key_capacity; ++k) {
    set_optional(s, p.key_age[k], c.sends[k].age);
    s[p.key_from[k]] = c.sends[k].from;
  }
}

Entry Slots::entry(const State& s, const BufferSlots& b) const {
  return {b.packet.load(s), optional_value(s, b.age), s[b.sender], s[b.sequence]};
}

void store_entries(State& s, const std::vector<BufferSlots>& places, const Entries& entries) {
  for (std::size_t k = 0; k < places.size(); ++k) {
    const Entry e = k < entries.size() ? entries[k] : Entry{Packet{}, -1, 0, 0};
    places[k].packet.store(s, e.packet);
    set_optional(s, places[k].age, e.age);
    s[places[k].sender] = e.sender;
    s[places[k].sequence] = e.sequence;
  }
}

const char* to_string(Bound bound) {
  static const char* const names[] = {"none",
                                      "pending-actions",
                                      "TOBcast-out",
                                      "local-out",
                                      "LBcast in flight",
                                      "TOBcast's buffer",
                                      "send keys",
                                      "seen ids",
                                      "sequence numbers",
                                      "the VN's out",
                                      "the VN message ids P7's monitor keeps",
                                      "the TOBcast messages P7's monitor keeps",
                                      "the VN message ids theorem-2's VN -> CN monitor keeps"};
  return names[static_cast<int>(bound)];
}

ContentOrder content_order(const Packet& p) {
  std::array<int, 8 + 2 * EmuConfig::key_capacity> fields{
      static_cast<int>(p.kind), p.message, p.from, p.count, p.last, p.zone, p.age, p.done.received};
  for (int k = 0; k < EmuConfig::key_capacity; ++k) {
    fields[8 + 2 * k] = p.done.sends[k].age;
    fields[9 + 2 * k] = p.done.sends[k].from;
  }
  return {fields, p.value};
}

bool Slots::past_bound(const State& s) const {
  return bound_met(s) != Bound::none;
}

Bound Slots::bound_met(const State& s) const {
  for (const PnSlots& p : pns)
    if (s[p.bound_met] != Bound::none)
      return s[p.bound_met];
  return Bound::none;
}

std::shared_ptr<const Slots> declare(tioa::Automaton& a, const EmuConfig& c) {
  auto slots = std::make_shared<Slots>();
  slots->config = c;
  if (c.vn == Vn::mc)
    slots->mc = std::make_shared<const McContext>(c);
  const McContext* mc = slots->mc.get();
  const bool warm = c.start == Start::warm;
  for (int i = 0; i < c.pns; ++i) {
    const std::string pn = "PN_" + std::to_string(i);
    PnSlots p;
    p.block.offset = a.layout().bits();
    p.up = a.boolean(pn + ".up", true);
    p.status = a.enumeration<Status>(pn + ".status", {"idle", "joining", "listening", "active"},
                                     Status::active);
    p.zone =
        a.optional_integer(pn + ".h", 0, c.zones - 1, warm ? std::optional<int>(0) : std::nullopt);
    p.value = value_slots(a, pn + ".val", c, mc);
    p.pending_join = age_variable(a, pn + ".pending_join", c);
    p.completed_join = age_variable(a, pn + ".completed_join", c);
    p.join_id = age_variable(a, pn + ".join_id", c);
    p.reset_sent = a.boolean(pn + ".reset_sent", false);
    p.proposed = a.boolean(pn + ".proposed", false);
    p.received = a.integer(pn + ".completed", 0, (1 << c.messages) - 1, 0);
    for (int k = 0; k < EmuConfig::key_capacity; ++k) {
      p.key_age[k] = age_variable(a, at(pn + ".key_age", k), c);
      p.key_from[k] = a.integer(at(pn + ".key_from", k), 0, c.pns - 1, 0);
    }
    for (int k = 0; k < EmuConfig::pending_capacity; ++k)
      p.pending.push_back(packet_slots(a, at(pn + ".pending", k), c, mc, false));
    for (int k = 0; k < EmuConfig::tob_out_capacity; ++k)
      p.tob_out.push_back(packet_slots(a, at(pn + ".tob_out", k), c, mc, true));
    for (int k = 0; k < EmuConfig::local_out_capacity; ++k)
      p.local_out.push_back(packet_slots(a, at(pn + ".local_out", k), c, mc, false));
    p.sequence = a.integer(pn + ".seq", 0, EmuConfig::sequence_capacity, 0);
    for (int k = 0; k < c.buffer; ++k) {
      p.buffer.push_back(buffer_slots(a, at(pn + ".buffer", k), c, mc, true));
    }
    for (int k = 0; k < EmuConfig::seen_capacity; ++k) {
      p.seen_age[k] = age_variable(a, at(pn + ".seen_age", k), c);
      p.seen_from[k] = a.integer(at(pn + ".seen_from", k), 0, c.pns - 1, 0);
    }
    p.sent_now = a.boolean(pn + ".sent_now", false);
    if (mc)
      p.cn_phase = a.integer(pn + ".cn_phase", 0, mc_inputs, 0);
    p.startup_wait = a.integer(pn + ".startup_wait", 0, 2 * c.stated_d_r(), 0);
    p.bound_met =
        a.enumeration<Bound>(pn + ".bound_met",
                             {"none", "pending", "tob_out", "local_out", "flight", "buffer", "keys",
                              "seen", "sequence", "out", "sent_ids", "taken", "delivery_ids"},
                             Bound::none);
    if (c.zones == 2) {
      p.point = a.integer(pn + ".x", 0, EmuConfig::points - 1, 0); // the start set places it
      p.move_wait = a.integer(pn + ".move_wait", 0, EmuConfig::move_period, 0);
    }
    p.block.bits = a.layout().bits() - p.block.offset;
    slots->pns.push_back(std::move(p));
  }
  // LBcast's packets, a block per sender, apart from the PNs' own variables so that a
  // receiver's step touches the sender's packets and not its VNE.
  for (int i = 0; i < c.pns; ++i) {
    PnSlots& p = slots->pns[i];
    p.flight_block.offset = a.layout().bits();
    for (int k = 0; k < EmuConfig::flight_capacity; ++k) {
      const std::string name = at("LBcast.from_" + std::to_string(i), k);
      FlightSlots f{packet_slots(a, name, c, mc, true), a.integer(name + ".elapsed", 0, c.d_p, 0),
                    a.integer(name + ".todo", 0, (1 << c.pns) - 1, 0),
                    a.integer(name + ".seq", 0, EmuConfig::sequence_capacity, 0), std::nullopt};
      if (c.zones == 2)
        f.oblig = a.integer(name + ".oblig", 0, (1 << c.pns) - 1, 0);
      p.flight.push_back(std::move(f));
    }
    p.flight_block.bits = a.layout().bits() - p.flight_block.offset;
  }
  slots->messages_left = a.integer("Env.messages_left", 0, c.messages, c.messages);
  slots->fails_left = a.integer("Env.fails_left", 0, c.fails, c.fails);
  if (c.zones == 2)
    slots->moves_left = a.integer("Env.moves_left", 0, c.moves, c.moves);
  for (int h = 0; h < c.zones; ++h) {
    const std::string zone = h == 0 ? "" : "_" + std::to_string(h); // B_0's keep their names
    slots->task_wait.push_back(a.integer("Monitor.task_wait" + zone, 0, c.age_cap(), 0));
    slots->task_sseq.push_back(
        a.optional_integer("Monitor.task_sseq" + zone, 0, EmuConfig::send_modulus - 1));
  }
  for (int m = 0; m < c.messages; ++m) {
    slots->message_wait.push_back(
        a.optional_integer(at("Monitor.message_wait", m), 0, c.age_cap()));
    if (c.zones == 2)
      slots->message_zone.push_back(a.integer(at("Monitor.message_zone", m), 0, 1, 0));
  }
  slots->check_ghosts = a.layout().bits();
  if (c.delivery_monitor) {
    DeliverySlots d;
    d.block.offset = a.layout().bits();
    for (int k = 0; k < EmuConfig::sent_capacity; ++k) {
      d.age[k] = age_variable(a, at("Monitor.vn_sent_age", k), c);
      d.from[k] = a.integer(at("Monitor.vn_sent_from", k), 0, c.pns - 1, 0);
      d.owed[k] = a.integer(at("Monitor.vn_owed", k), 0, (1 << (c.pns + 1)) - 1, 0);
      d.wait[k] = a.optional_integer(at("Monitor.vn_wait", k), 0, c.age_cap());
      if (c.zones == 2) {
        d.zone.push_back(a.integer(at("Monitor.vn_zone", k), 0, 1, 0));
        d.vn_wait.push_back(a.optional_integer(at("Monitor.vn_vn_wait", k), 0, c.age_cap()));
      }
    }
    // At most one reset a PN a quantum (restart fires once a join, D7).
    for (int k = 0; k < c.pns; ++k)
      d.reset_tag.push_back(
          a.integer(at("Monitor.reset_tag", k), 0, c.pns * (EmuConfig::sequence_capacity + 1), 0));
    d.block.bits = a.layout().bits() - d.block.offset;
    slots->delivery = d;
  }
  if (c.refinement_monitor)
    for (int h = 0; h < c.zones; ++h) { // one reference replica a zone
      const std::string m = h == 0 ? "Monitor." : "Monitor_1.";
      RefinementSlots r;
      r.block.offset = a.layout().bits();
      r.abstract = value_slots(a, m + "val_abs", c, mc);
      r.done_received = a.integer(m + "done_received", 0, (1 << c.messages) - 1, 0);
      for (int k = 0; k < EmuConfig::key_capacity; ++k) {
        r.done_age[k] = age_variable(a, at(m + "done_age", k), c);
        r.done_from[k] = a.integer(at(m + "done_from", k), 0, c.pns - 1, 0);
      }
      for (int k = 0; k < c.buffer; ++k) {
        r.taken.push_back(buffer_slots(a, at(m + "taken", k), c, mc, false));
      }
      for (int k = 0; k < EmuConfig::sent_capacity; ++k) {
        r.sent_age[k] = age_variable(a, at(m + "sent_age", k), c);
        r.sent_from[k] = a.integer(at(m + "sent_from", k), 0, c.pns - 1, 0);
      }
      r.refused_by = a.integer(m + "refused_by", 0, c.pns, 0);
      r.was_alive = a.boolean(m + "was_alive", warm);
      r.live_restart = a.boolean(m + "live_restart", false);
      r.block.bits = a.layout().bits() - r.block.offset;
      slots->refinement.push_back(std::move(r));
    }
  return slots;
}

} // namespace vn_emulation
