#include "models/vn_emulation/refinement.hpp"

#include <algorithm>

#include "models/vn_emulation/key_set.hpp"
#include "models/vn_emulation/predicates.hpp"
#include "models/vn_emulation/vn_steps.hpp"

namespace vn_emulation {

namespace {

// A TOBcast message as the monitor remembers it: its tag and its content without a
// join-ack's payload.
Entry remembered(const Entry& e) {
  Entry out = e;
  out.packet.value = {};
  out.packet.done = {};
  return out;
}

bool same(const Entry& x, const Entry& y) {
  return x.packet == y.packet && x.age == y.age && x.sender == y.sender && x.sequence == y.sequence;
}

Entries load_taken(const Slots& slots, const RefinementSlots& r, const State& s) {
  Entries out;
  for (const BufferSlots& b : r.taken)
    if (s[b.packet.kind] != static_cast<int>(Kind::none))
      out.push_back(slots.entry(s, b));
  return out;
}

void store_taken(const RefinementSlots& r, State& s, Entries taken) {
  // TOBcast's order, then the content, for tags that repeat (slots.hpp).
  taken.sort([](const Entry& x, const Entry& y) { return delivered_before(x, y, true); });
  store_entries(s, r.taken, taken);
}

// The reference replica after this instant's TOBcast messages, executed in TOBcast's
// order from its state at the instant's start, as a VNE executes them (002:446–452; D9:
// a key recorded when executed; D5: a reset restarts it).
struct Reference {
  VnValue val;
  int done_received = 0;
  // Completed sends (and, two zones, reports), with room for this instant's; the sends
  // made in this instant.
  tioa::FixedList<Key, EmuConfig::key_capacity + EmuConfig::max_buffer_capacity> done;
  tioa::FixedList<Key, EmuConfig::max_buffer_capacity> sent;
};

Reference replay(const Slots& slots, const State& s, int h) {
  const RefinementSlots& r = slots.refinement[h];
  Reference ref{r.abstract.load(s),
                s[r.done_received],
                load_keys<EmuConfig::max_buffer_capacity>(s, r.done_age, r.done_from),
                {}};
  for (const Entry& e : load_taken(slots, r, s)) { // stored in delivery order
    const Packet& m = e.packet;
    if (m.kind == Kind::simulate_receive && m.age >= 0) { // two zones: the neighbour's report
      const Key id{m.age, m.from};
      if (std::find(ref.done.begin(), ref.done.end(), id) == ref.done.end()) {
        vn_receive_neighbour(slots, ref.val, m.count);
        ref.done.push_back(id);
      }
    } else if (m.kind == Kind::simulate_receive) {
      if (((ref.done_received >> m.message) & 1) == 0 &&
          vn_receive(slots, ref.val, h, m.from, m.count))
        ref.done_received |= 1 << m.message;
    } else if (m.kind == Kind::simulate_send) {
      const Key oid{m.age, m.from};
      if (std::find(ref.done.begin(), ref.done.end(), oid) == ref.done.end() &&
          vn_send_enabled(slots, ref.val, m.count, m.last)) {
        vn_send(slots, ref.val);
        ref.done.push_back(oid);
        ref.sent.push_back(oid);
      }
    } else if (m.kind == Kind::reset) {
      ref.val = VnValue{};
      ref.done_received = 0;
      ref.done.clear();
    }
  }
  return ref;
}

} // namespace

void monitor_delivery(const Slots& slots, State& s, int pn, const Entry& entry) {
  if (slots.refinement.empty())
    return;
  const int h = entry.packet.zone;
  const RefinementSlots& r = slots.refinement[h];
  Entries taken = load_taken(slots, r, s);
  const Entry id = remembered(entry);
  if (std::any_of(taken.begin(), taken.end(), [&](const Entry& e) { return same(e, id); }))
    return; // taken at another PN's delivery
  if (taken.size() == r.taken.size()) {
    slots.exceed(s, pn, Bound::taken);
    return;
  }
  taken.push_back(id);
  store_taken(r, s, std::move(taken));
  // P6: a reset delivered while VN_0 is alive, as it was at the last tick.
  if (entry.packet.kind == Kind::reset && s[r.was_alive] && vn_alive(slots, s, h))
    s[r.live_restart] = true;
}

void monitor_transmit(const Slots& slots, State& s, int pn, const Packet& m) {
  if (slots.refinement.empty())
    return;
  const RefinementSlots& r = slots.refinement[m.zone];
  const Key id{m.age, m.from};
  auto sent = load_keys<EmuConfig::max_buffer_capacity>(s, r.sent_age, r.sent_from);
  for (const Key& k : replay(slots, s, m.zone).sent)
    sent.push_back(k);
  if (std::find(sent.begin(), sent.end(), id) == sent.end() && s[r.refused_by] == 0)
    s[r.refused_by] = pn + 1;
}

namespace {
void monitor_tick_zone(const Slots& slots, State& s, int h, bool alive);
} // namespace

void monitor_tick(const Slots& slots, State& s, const std::array<bool, 2>& alive) {
  for (std::size_t h = 0; h < slots.refinement.size(); ++h)
    monitor_tick_zone(slots, s, static_cast<int>(h), alive[h]);
}

namespace {
void monitor_tick_zone(const Slots& slots, State& s, int h, bool alive) {
  const RefinementSlots& r = slots.refinement[h];
  Reference ref = replay(slots, s, h);
  for (const Key& id : ref.sent)
    if (add_key(s, r.sent_age, r.sent_from, id) == KeyAdded::full)
      slots.exceed(s, 0, Bound::sent_ids);
  s[r.was_alive] = alive;
  if (!alive) // what a failed VN_0 held no longer matters: one ghost value
    ref = Reference{};
  if (ref.done.size() > r.done_age.size()) {
    slots.exceed(s, 0, Bound::sent_ids);
    ref.done.truncate(r.done_age.size());
  }
  r.abstract.store(s, ref.val);
  s[r.done_received] = ref.done_received;
  store_keys(s, r.done_age, r.done_from, ref.done);
  // Every PN delivers a TOBcast message in one instant, ts + d_p + ε (it has it by ts +
  // d_p, 002:37, and delivery is urgent): the instant's messages are done with.
  store_taken(r, s, {});
}
} // namespace

void monitor_age(const Slots& slots, State& s) {
  const int horizon = slots.config.horizon();
  for (const RefinementSlots& r : slots.refinement) {
    for (const auto* ages : {&r.done_age, &r.sent_age})
      for (const auto& age : *ages)
        s.advance(age);
    collect(s, r.done_age, r.done_from, horizon);
    collect(s, r.sent_age, r.sent_from, horizon);
  }
}

bool restarted_live(const Slots& slots, const State& s) {
  return std::any_of(slots.refinement.begin(), slots.refinement.end(),
                     [&](const RefinementSlots& r) { return s[r.live_restart]; });
}

std::optional<std::string> refinement_failure(const Slots& slots, const State& s) {
  const bool two = slots.refinement.size() == 2;
  for (std::size_t z = 0; z < slots.refinement.size(); ++z) {
    const int h = static_cast<int>(z);
    const RefinementSlots& r = slots.refinement[z];
    const std::string vn = two ? "VN_" + std::to_string(h) : "VN";
    const VnValue abstract = replay(slots, s, h).val;
    if (s[r.refused_by] != 0)
      return "PN_" + std::to_string(s[r.refused_by] - 1) + " transmitted a message the abstract " +
             vn + " did not send (its state: " + describe(slots, abstract) + ")";
    if (urgent(slots, s))
      continue;
    for (int i = 0; i < slots.config.pns; ++i) {
      const PnSlots& p = slots.pns[i];
      if (vne_zone(slots, s, i) != h || s[p.status] != Status::active)
        continue;
      const VnValue held = p.value.load(s);
      if (held != abstract)
        return "the active replica PN_" + std::to_string(i) + " holds (" + describe(slots, held) +
               ") where time passes, the abstract " + vn + " (" + describe(slots, abstract) + ")";
    }
  }
  return std::nullopt;
}

} // namespace vn_emulation
