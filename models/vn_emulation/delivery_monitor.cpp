#include "models/vn_emulation/delivery_monitor.hpp"

#include <algorithm>
#include <tuple>
#include <vector>

namespace vn_emulation {

namespace {

struct Record {
  Key id;
  int owed = 0;  // bit i: CN_i is still owed the message
  int wait = -1; // quanta since the send while owed; -1 (⊥) once paid
};

std::vector<Record> load(const DeliverySlots& d, const State& s) {
  std::vector<Record> out;
  for (std::size_t k = 0; k < d.age.size(); ++k)
    if (!s.is_bottom(d.age[k]))
      out.push_back({{s[d.age[k]], s[d.from[k]]}, s[d.owed[k]], optional_value(s, d.wait[k])});
  return out;
}

void store(const DeliverySlots& d, State& s, std::vector<Record> records) {
  std::sort(records.begin(), records.end(), [](const Record& x, const Record& y) {
    return std::tie(x.id.age, x.id.from) < std::tie(y.id.age, y.id.from);
  });
  for (std::size_t k = 0; k < d.age.size(); ++k) {
    const Record r = k < records.size() ? records[k] : Record{{-1, 0}, 0, -1};
    set_optional(s, d.age[k], r.id.age);
    s[d.from[k]] = r.id.from;
    s[d.owed[k]] = r.owed;
    set_optional(s, d.wait[k], r.wait);
  }
}

// Takes the clients in `paid` off every record (of `id` only, when given).
void pay(const Slots& slots, State& s, int paid, const Key* id) {
  std::vector<Record> records = load(*slots.delivery, s);
  for (Record& r : records)
    if (!id || r.id == *id) {
      r.owed &= ~paid;
      if (r.owed == 0)
        r.wait = -1;
    }
  store(*slots.delivery, s, std::move(records));
}

} // namespace

void delivery_transmit(const Slots& slots, State& s, const Packet& m) {
  if (!slots.delivery)
    return;
  std::vector<Record> records = load(*slots.delivery, s);
  const Key id{m.age, m.from};
  if (std::any_of(records.begin(), records.end(), [&](const Record& r) { return r.id == id; }))
    return; // sent before, by this replica or another
  if (records.size() == slots.delivery->age.size()) {
    slots.exceed(s, m.from, Bound::delivery_ids);
    return;
  }
  int up = 0;
  for (int i = 0; i < slots.config.pns; ++i)
    if (s[slots.pns[i].up])
      up |= 1 << i;
  records.push_back({id, up, up != 0 ? 0 : -1});
  store(*slots.delivery, s, std::move(records));
}

void delivery_receive(const Slots& slots, State& s, int pn, const Key& id) {
  if (slots.delivery)
    pay(slots, s, 1 << pn, &id);
}

void delivery_fail(const Slots& slots, State& s, int pn) {
  if (slots.delivery)
    pay(slots, s, 1 << pn, nullptr);
}

void delivery_restart(const Slots& slots, State& s) {
  if (!slots.delivery)
    return;
  for (const auto& wait : slots.message_wait)
    s.set_bottom(wait);
}

void delivery_tick(const Slots& slots, State& s) {
  if (!slots.delivery)
    return;
  const EmuConfig& c = slots.config;
  std::vector<Record> kept;
  for (Record r : load(*slots.delivery, s)) {
    if (r.owed != 0)
      r.wait = std::min(r.wait + 1, c.age_cap());
    r.id.age = std::min(r.id.age + 1, c.age_cap());
    if (r.owed != 0 || r.id.age < c.horizon())
      kept.push_back(r);
  }
  store(*slots.delivery, s, std::move(kept));
}

int vn_to_cn_wait(const Slots& slots, const State& s) {
  int worst = 0;
  if (slots.delivery)
    for (const Record& r : load(*slots.delivery, s))
      worst = std::max(worst, r.wait);
  return worst;
}

} // namespace vn_emulation
