#include "proofs/vn_layer/round_legal_set.hpp"

#include <stdexcept>

#include "models/vn_layer/names.hpp"
#include "models/vn_layer/round_tags.hpp"
#include "models/vn_layer/vn.hpp"

namespace vn_layer {

using tioa::State;
using tioa::Word;

namespace {

template <class T> tioa::Variable<T> variable(const tioa::Automaton& a, const std::string& name) {
  return tioa::find_variable<T>(a, name);
}

std::string indexed(const std::string& name, int i) {
  return name + "[" + std::to_string(i) + "]";
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

} // namespace

RoundLegalSet::RoundLegalSet(const tioa::Automaton& layer, const VnConfig& c)
    : config_(c), lattice_(c.lattice()), words_(layer.words()), all_(layer.layout().variables()),
      bcast_phase_(variable<int>(layer, "VLBcast.phase")),
      bcast_epoch_(variable<int>(layer, "VLBcast.epoch")),
      bcast_overflow_(variable<bool>(layer, "VLBcast.overflow")) {
  for (int i = 0; i < c.cns; ++i) {
    const std::string p = names::cn_name(i) + ".";
    cns_.push_back({variable<bool>(layer, p + "failed"),
                    variable<bool>(layer, p + "late_target_update"),
                    variable<int>(layer, p + "phase"), variable<int>(layer, p + "epoch"),
                    variable<int>(layer, p + "x"), variable<int>(layer, p + "target"),
                    variable<int>(layer, p + "round"), variable<int>(layer, p + "next_exch"),
                    variable<int>(layer, p + "next_target"), variable<int>(layer, p + "zone")});
    zone_of_.push_back(variable<int>(layer, indexed("Zones.zone", i)));
    active_.push_back(variable<bool>(layer, indexed("Zones.active", i)));
  }
  for (RegionId h = 0; h < lattice_.regions(); ++h) {
    const std::string p = names::vn_name(h) + ".";
    Vn vn{variable<bool>(layer, p + "failed"),
          variable<bool>(layer, p + "overflow"),
          variable<int>(layer, p + "phase"),
          variable<int>(layer, p + "epoch"),
          variable<int>(layer, p + "vn_done"),
          variable<int>(layer, p + "target_done"),
          variable<int>(layer, p + "task"),
          {},
          {},
          {},
          {},
          {},
          {}};
    for (int i = 0; i < c.cns; ++i) {
      vn.M.push_back(variable<int>(layer, indexed(p + "M", i)));
      vn.M_round.push_back(variable<int>(layer, indexed(p + "M_round", i)));
    }
    for (const RegionId g : v_zones(lattice_, h))
      vn.V_round.push_back(variable<int>(layer, indexed(p + "V_round", g)));
    for (int slot = 0; slot < buffer_slots; ++slot)
      vn.buffer.push_back(variable<int>(layer, indexed(p + "buffer", slot)).slot);
    // Everything but what a representative keeps (failed, overflow) or sets to a round tag
    // of an earlier round (epoch, V_round, vn_done, target_done).
    for (const tioa::VariableInfo& v : all_) {
      if (!starts_with(v.name, p))
        continue;
      const std::string own = v.name.substr(p.size());
      if (own == "failed" || own == "overflow" || own == "epoch" || own == "vn_done" ||
          own == "target_done" || starts_with(own, "V_round["))
        continue;
      vn.to_init.push_back(v.slot());
      vn.init_codes.push_back(v.initial_code.value_or(0));
    }
    vns_.push_back(std::move(vn));
    vn_failed_.push_back(variable<bool>(layer, indexed("Zones.vn_failed", h)));
    occupied_for_.push_back(variable<int>(layer, indexed("Zones.occupied_for", h)));
  }
  for (const tioa::VariableInfo& v : all_) {
    if (!starts_with(v.name, "VLBcast.") || v.name == "VLBcast.phase" ||
        v.name == "VLBcast.epoch" || v.name == "VLBcast.overflow")
      continue;
    // vlbcast.cpp: a client place is taken while `<kind>_pending[i]`, a VN's place while a
    // receiver's bit of `vn_update_to[h]` or `target_update_to[h]` is set.
    if (v.name.find("_pending[") != std::string::npos ||
        starts_with(v.name, "VLBcast.vn_update_to[") ||
        starts_with(v.name, "VLBcast.target_update_to[")) {
      bcast_in_flight_.push_back(v.slot());
    } else {
      bcast_contents_.push_back(v.slot());
      bcast_empty_.push_back(v.initial_code.value_or(0));
    }
  }
}

std::optional<std::string> RoundLegalSet::broken(const Word* state) const {
  std::string why;
  if (first_broken(state, &why))
    return why;
  return std::nullopt;
}

bool RoundLegalSet::first_broken(const Word* state, std::string* why) const {
  const State s(state, 0);
  // The clause's text is built only when asked for: the search calls this on every state at
  // a round's first instant, and most of them break R1.
  const auto fail = [&](const auto& text) {
    if (why)
      *why = text();
    return true;
  };
  const int n = config_.cns, regions = lattice_.regions();
  // (R5) realtime kδ, k ≥ 1, in every copy.
  const auto round_start = [&](const tioa::Variable<int>& phase, const tioa::Variable<int>& epoch) {
    return s[phase] == 0 && s[epoch] != 0;
  };
  for (int i = 0; i < n; ++i)
    if (!round_start(cns_[static_cast<std::size_t>(i)].phase,
                     cns_[static_cast<std::size_t>(i)].epoch))
      return fail([&] {
        return std::string("R5: " + names::cn_name(i) +
                           "'s realtime is not a round start k*delta, k >= 1");
      });
  for (RegionId h = 0; h < regions; ++h)
    if (!round_start(vns_[static_cast<std::size_t>(h)].phase,
                     vns_[static_cast<std::size_t>(h)].epoch))
      return fail([&] {
        return std::string("R5: " + names::vn_name(h) +
                           "'s realtime is not a round start k*delta, k >= 1");
      });
  if (!round_start(bcast_phase_, bcast_epoch_))
    return fail(
        [&] { return std::string("R5: VLBcast's realtime is not a round start k*delta, k >= 1"); });
  // (R5) the copies agree; (R1) the active CNs; (R2) their VNs.
  std::uint64_t occupied = 0; // a bit per zone (at most 16: rows, cols <= 4)
  for (int i = 0; i < n; ++i) {
    const Cn& cn = cns_[static_cast<std::size_t>(i)];
    const auto name = [i] { return names::cn_name(i); };
    const bool active = !s[cn.failed];
    if (s[active_[static_cast<std::size_t>(i)]] != active)
      return fail([&] {
        return std::string("R5: Zones' record of whether " + name() + " is active is wrong");
      });
    const RegionId zone = lattice_.region_of(s[cn.x]);
    const int announced = s[cn.zone];
    if (announced != s[zone_of_[static_cast<std::size_t>(i)]])
      return fail(
          [&] { return std::string("R5: " + name() + "'s record of its zone and Zones' differ"); });
    // A CN that crosses a border at the tick of the round start announces it (enter_i) by
    // a zero-time step after the round start: outside L_round (models/vn_layer/README.md).
    if (announced != zone)
      return fail([&] {
        return std::string("R5: " + name() + " has crossed into zone " + std::to_string(zone) +
                           " at this instant and not yet announced it (enter_" + std::to_string(i) +
                           " follows the tick)");
      });
    if (!active)
      continue;
    occupied |= std::uint64_t{1} << zone;
    for (const auto& counter : {cn.round, cn.next_exch, cn.next_target})
      if (s.is_bottom(counter) || s[counter] != this_round)
        return fail([&] {
          return std::string("R1: " + name() + "'s round counters are not all this round's");
        });
    if (s.is_bottom(cn.target))
      return fail([&] { return std::string("R1: " + name() + " has no target"); });
    if (s[cn.x] != s[cn.target])
      return fail([&] {
        return std::string("R1: " + name() + " is not on its target: x = " +
                           std::to_string(s[cn.x]) + ", x* = " + std::to_string(s[cn.target]));
      });
    if (s[vns_[static_cast<std::size_t>(zone)].failed])
      return fail([&] {
        return std::string("R2: " + name() + " is in zone " + std::to_string(zone) +
                           ", whose VN is failed");
      });
  }
  for (RegionId h = 0; h < regions; ++h) {
    const Vn& vn = vns_[static_cast<std::size_t>(h)];
    const auto name = [h] { return names::vn_name(h); };
    if (s[vn_failed_[static_cast<std::size_t>(h)]] != s[vn.failed])
      return fail([&] {
        return std::string("R5: Zones' record of whether " + name() + " is failed is wrong");
      });
    if (!(occupied >> h & 1) && s[occupied_for_[static_cast<std::size_t>(h)]] != 0)
      return fail([&] {
        return std::string("R5: zone " + std::to_string(h) +
                           " holds no active CN but counts occupancy");
      });
    for (const tioa::Slot& place : vn.buffer)
      if (s.code(place) != 0) // Buffered::none
        return fail([&] { return std::string("R3: " + name() + "'s send-buffer is not empty"); });
    if (s[vn.vn_done] == this_round || s[vn.target_done] == this_round)
      return fail(
          [&] { return std::string("R3: " + name() + " has handled a trigger of this round"); });
    for (std::size_t i = 0; i < vn.M.size(); ++i)
      if (!s.is_bottom(vn.M[i]) && s[vn.M_round[i]] == this_round)
        return fail(
            [&] { return std::string("R3: " + name() + "'s M holds an entry of this round"); });
    for (const auto& tag : vn.V_round)
      if (s[tag] == this_round)
        return fail(
            [&] { return std::string("R3: " + name() + "'s V holds an entry of this round"); });
  }
  // (R4)
  for (const tioa::Slot& place : bcast_in_flight_)
    if (s.code(place) != 0)
      return fail([&] {
        return std::string("R4: VLBcast holds a message (" + std::string(place.name) + ")");
      });
  return false;
}

void RoundLegalSet::canonicalise(Word* state) const {
  State s(state, 0);
  for (const Cn& cn : cns_) {
    s[cn.epoch] = last_round;
    s[cn.late_target_update] = false;
    if (s[cn.failed])
      for (const auto& internal : {cn.target, cn.round, cn.next_exch, cn.next_target})
        s.set_bottom(internal);
  }
  for (const Vn& vn : vns_) {
    for (std::size_t j = 0; j < vn.to_init.size(); ++j)
      s.set_code(vn.to_init[j], vn.init_codes[j]);
    s[vn.epoch] = last_round;
    s[vn.vn_done] = last_round; // what a reset writes in round 1 (round_zero)
    s[vn.target_done] = last_round;
    for (const auto& tag : vn.V_round)
      s[tag] = last_round;
  }
  s[bcast_epoch_] = last_round;
  for (std::size_t j = 0; j < bcast_contents_.size(); ++j)
    s.set_code(bcast_contents_[j], bcast_empty_[j]);
}

std::optional<RegionId> RoundLegalSet::stale_reader(const Word* state) const {
  const State s(state, 0);
  for (RegionId h = 0; h < lattice_.regions(); ++h) {
    const Vn& vn = vns_[static_cast<std::size_t>(h)];
    if (!s[vn.failed] && s[vn.target_done] == this_round && s[vn.vn_done] != this_round)
      return h;
  }
  return std::nullopt;
}

bool RoundLegalSet::overflowed(const Word* state) const {
  const State s(state, 0);
  if (s[bcast_overflow_])
    return true;
  for (const Vn& vn : vns_)
    if (s[vn.overflow])
      return true;
  return false;
}

std::vector<Word> RoundLegalSet::representatives() const {
  const int n = config_.cns, points = lattice_.points(), regions = lattice_.regions();
  std::vector<Word> base(words_ + 1, 0);
  {
    State s(base.data(), 0);
    for (const tioa::VariableInfo& v : all_)
      s.set_code(v.slot(), v.initial_code.value_or(0));
  }
  std::vector<Word> out;
  // Each CN: 2·points choices, active at a point (even) or failed at one (odd).
  std::vector<int> cn_choice(static_cast<std::size_t>(n), 0);
  for (;;) {
    std::vector<Word> words = base;
    State s(words.data(), 0);
    std::vector<std::uint8_t> occupied(static_cast<std::size_t>(regions), 0);
    for (int i = 0; i < n; ++i) {
      const Cn& cn = cns_[static_cast<std::size_t>(i)];
      const int choice = cn_choice[static_cast<std::size_t>(i)];
      const int x = choice / 2;
      const bool failed = choice % 2 == 1;
      const RegionId zone = lattice_.region_of(x);
      s[cn.x] = x;
      s[cn.zone] = zone;
      s[zone_of_[static_cast<std::size_t>(i)]] = zone;
      s[cn.failed] = failed;
      s[active_[static_cast<std::size_t>(i)]] = !failed;
      if (!failed) {
        occupied[static_cast<std::size_t>(zone)] = 1;
        s[cn.target] = x;
        for (const auto& counter : {cn.round, cn.next_exch, cn.next_target})
          s[counter] = this_round;
      }
    }
    // The free choices of the VNs and Zones: a failed VN where no active CN is, and the
    // count of occupancy (0..d_r) where one is.
    std::vector<int> radix, digit;
    for (RegionId h = 0; h < regions; ++h)
      radix.push_back(occupied[static_cast<std::size_t>(h)] ? config_.d_r + 1 : 2);
    digit.assign(radix.size(), 0);
    for (;;) {
      std::vector<Word> full = words;
      State t(full.data(), 0);
      for (RegionId h = 0; h < regions; ++h) {
        const auto k = static_cast<std::size_t>(h);
        const bool vn_failed = !occupied[k] && digit[k] == 1;
        t[vns_[k].failed] = vn_failed;
        t[vn_failed_[k]] = vn_failed;
        t[occupied_for_[k]] = occupied[k] ? digit[k] : 0;
      }
      canonicalise(full.data());
      if (auto why = broken(full.data()))
        throw std::logic_error("vn-layer L_round: a representative is not in L_round: " + *why);
      out.insert(out.end(), full.begin(), full.begin() + words_);
      std::size_t d = 0;
      while (d < digit.size() && ++digit[d] == radix[d])
        digit[d++] = 0;
      if (d == digit.size())
        break;
    }
    std::size_t i = 0;
    while (i < cn_choice.size() && ++cn_choice[i] == 2 * points)
      cn_choice[i++] = 0;
    if (i == cn_choice.size())
      break;
  }
  return out;
}

} // namespace vn_layer
