#include "models/vn_emulation/delivery_monitor.hpp"

#include <algorithm>
#include <tuple>

#include "models/vn_emulation/predicates.hpp"

namespace vn_emulation {

namespace {

struct Record {
  Key id;
  int owed = 0;     // bit i: CN_i is still owed the message; bit pns: the neighbouring VN
  int wait = -1;    // quanta since the send while a client is owed; -1 (⊥) once none is
  int zone = 0;     // the VN that sent it (two zones)
  int vn_wait = -1; // quanta since the send while the neighbouring VN is owed it
};

using Records = tioa::FixedList<Record, EmuConfig::sent_capacity + 1>; // room for a new one

Records load(const DeliverySlots& d, const State& s) {
  Records out;
  for (std::size_t k = 0; k < d.age.size(); ++k)
    if (!s.is_bottom(d.age[k]))
      out.push_back({{s[d.age[k]], s[d.from[k]]},
                     s[d.owed[k]],
                     optional_value(s, d.wait[k]),
                     d.zone.empty() ? 0 : static_cast<int>(s[d.zone[k]]),
                     d.vn_wait.empty() ? -1 : optional_value(s, d.vn_wait[k])});
  return out;
}

void store(const DeliverySlots& d, State& s, Records records) {
  records.sort([](const Record& x, const Record& y) {
    return std::tie(x.id.age, x.id.from) < std::tie(y.id.age, y.id.from);
  });
  for (std::size_t k = 0; k < d.age.size(); ++k) {
    const Record r = k < records.size() ? records[k] : Record{{-1, 0}, 0, -1, 0, -1};
    set_optional(s, d.age[k], r.id.age);
    s[d.from[k]] = r.id.from;
    s[d.owed[k]] = r.owed;
    set_optional(s, d.wait[k], r.wait);
    if (!d.zone.empty()) {
      s[d.zone[k]] = r.zone;
      set_optional(s, d.vn_wait[k], r.vn_wait);
    }
  }
}

// Takes the owed bits `paid` off the records `which` selects, and ends the waits with
// nothing left to wait for.
template <class Which> void pay(const Slots& slots, State& s, int paid, Which which) {
  Records records = load(*slots.delivery, s);
  const int vn_bit = 1 << slots.config.pns;
  for (Record& r : records)
    if (which(r)) {
      r.owed &= ~paid;
      if ((r.owed & (vn_bit - 1)) == 0)
        r.wait = -1;
      if ((r.owed & vn_bit) == 0)
        r.vn_wait = -1;
    }
  store(*slots.delivery, s, std::move(records));
}

} // namespace

void delivery_transmit(const Slots& slots, State& s, const Packet& m) {
  if (!slots.delivery)
    return;
  Records records = load(*slots.delivery, s);
  const Key id{m.age, m.from};
  if (std::any_of(records.begin(), records.end(), [&](const Record& r) { return r.id == id; }))
    return; // sent before, by this replica or another
  if (records.size() == slots.delivery->age.size()) {
    slots.exceed(s, m.from, Bound::delivery_ids);
    return;
  }
  Record r{id, 0, -1, m.zone, -1};
  for (int i = 0; i < slots.config.pns; ++i) // the clients in B_g, up now
    if (s[slots.pns[i].up] && point_zone(slots, s, i) == m.zone)
      r.owed |= 1 << i;
  if (r.owed != 0)
    r.wait = 0;
  if (slots.config.zones == 2 && vn_alive(slots, s, 1 - m.zone)) { // the neighbour, if alive
    r.owed |= 1 << slots.config.pns;
    r.vn_wait = 0;
  }
  records.push_back(r);
  store(*slots.delivery, s, std::move(records));
}

void delivery_receive(const Slots& slots, State& s, int pn, const Key& id) {
  if (slots.delivery)
    pay(slots, s, 1 << pn, [&](const Record& r) { return r.id == id; });
}

void delivery_vn_executed(const Slots& slots, State& s, const Key& id) {
  if (slots.delivery)
    pay(slots, s, 1 << slots.config.pns, [&](const Record& r) { return r.id == id; });
}

void delivery_fail(const Slots& slots, State& s, int pn) {
  if (slots.delivery)
    pay(slots, s, 1 << pn, [](const Record&) { return true; });
}

void delivery_move(const Slots& slots, State& s, int pn) {
  const int here = point_zone(slots, s, pn);
  if (slots.delivery) // a client that left B_g is not in B_g throughout
    pay(slots, s, 1 << pn, [&](const Record& r) { return r.zone != here; });
}

void delivery_tobcast(const Slots& slots, State& s, int pn, const Entry& entry) {
  if (!slots.delivery || entry.packet.kind != Kind::reset)
    return;
  // Every PN delivers a reset in the one instant ts + d_p + ε (ε ≥ 1; with ε = 0 a late
  // copy may come after its turn, D12d, and counts as delivered again), so the tags of
  // this instant's resets tell a first delivery from a later one.
  const int tag = 1 + entry.sender * (EmuConfig::sequence_capacity + 1) + entry.sequence;
  tioa::FixedList<int, 4> tags; // at most pns (3), one more to add
  for (const auto& v : slots.delivery->reset_tag)
    if (s[v] != 0)
      tags.push_back(s[v]);
  if (std::find(tags.begin(), tags.end(), tag) != tags.end())
    return;
  if (tags.size() == slots.delivery->reset_tag.size()) {
    slots.exceed(s, pn, Bound::delivery_ids);
    return;
  }
  tags.push_back(tag);
  tags.sort([](int x, int y) { return x < y; });
  for (std::size_t k = 0; k < slots.delivery->reset_tag.size(); ++k)
    s[slots.delivery->reset_tag[k]] = k < tags.size() ? tags[k] : 0;
  // VN_h restarts (h the reset's zone): what it owed and what was owed to it ends.
  const int h = entry.packet.zone;
  for (std::size_t m = 0; m < slots.message_wait.size(); ++m)
    if (slots.message_zone.empty() || s[slots.message_zone[m]] == h)
      s.set_bottom(slots.message_wait[m]);
  pay(slots, s, 1 << slots.config.pns, [&](const Record& r) { return r.zone != h; });
}

void delivery_tick(const Slots& slots, State& s) {
  if (!slots.delivery)
    return;
  const EmuConfig& c = slots.config;
  const int vn_bit = 1 << c.pns;
  Records kept;
  for (Record r : load(*slots.delivery, s)) {
    if ((r.owed & vn_bit) && !vn_alive(slots, s, 1 - r.zone)) { // not alive throughout
      r.owed &= ~vn_bit;
      r.vn_wait = -1;
    }
    if (r.owed & (vn_bit - 1))
      r.wait = std::min(r.wait + 1, c.age_cap());
    if (r.owed & vn_bit)
      r.vn_wait = std::min(r.vn_wait + 1, c.age_cap());
    r.id.age = std::min(r.id.age + 1, c.age_cap());
    if (r.owed != 0 || r.id.age < c.horizon())
      kept.push_back(r);
  }
  store(*slots.delivery, s, std::move(kept));
  for (const auto& v : slots.delivery->reset_tag)
    s[v] = 0;
}

namespace {

// The longest of the records' waits `field` (0 when none).
int longest(const Slots& slots, const State& s, int Record::*field) {
  int worst = 0;
  if (slots.delivery)
    for (const Record& r : load(*slots.delivery, s))
      worst = std::max(worst, r.*field);
  return worst;
}

} // namespace

int vn_to_cn_wait(const Slots& slots, const State& s) {
  return longest(slots, s, &Record::wait);
}

int vn_to_vn_wait(const Slots& slots, const State& s) {
  return longest(slots, s, &Record::vn_wait);
}

} // namespace vn_emulation
