#include "models/vn_layer/observers.hpp"

#include "models/vn_layer/cn.hpp"
#include "models/vn_layer/names.hpp"
#include "models/vn_layer/round_tags.hpp"
#include "models/vn_layer/vn.hpp"

namespace vn_layer {

using tioa::find_variable;

Observers::Observers(const tioa::Automaton& layer, const VnConfig& c)
    : lattice_(c.lattice()), channel_overflow_(find_variable<bool>(layer, "VLBcast.overflow")) {
  for (int i = 0; i < c.cns; ++i) {
    const std::string cn = names::cn_name(i) + ".";
    cns_.push_back({find_variable<bool>(layer, cn + "failed"),
                    find_variable<bool>(layer, cn + "late_target_update"),
                    find_variable<int>(layer, cn + "phase"), find_variable<int>(layer, cn + "x"),
                    find_variable<int>(layer, cn + "target"),
                    find_variable<int>(layer, cn + "round"),
                    find_variable<int>(layer, cn + "next_exch"),
                    find_variable<int>(layer, cn + "next_target")});
  }
  for (RegionId h = 0; h < lattice_.regions(); ++h) {
    const std::string vn = names::vn_name(h) + ".";
    VnSlots slots{find_variable<bool>(layer, vn + "failed"),
                  find_variable<bool>(layer, vn + "late_cn_update"),
                  find_variable<bool>(layer, vn + "late_vn_update"),
                  find_variable<bool>(layer, vn + "overflow"),
                  find_variable<int>(layer, vn + "epoch"),
                  find_variable<int>(layer, vn + "y_round"),
                  v_zones(lattice_, h),
                  {}};
    for (const RegionId z : slots.zones)
      slots.y.push_back(find_variable<int>(layer, vn + "y[" + std::to_string(z) + "]"));
    vns_.push_back(std::move(slots));
  }
}

std::optional<std::string> Observers::round_timing_failure(const tioa::State& s) const {
  for (std::size_t h = 0; h < vns_.size(); ++h) {
    if (s[vns_[h].late_cn])
      return "(T1) a cn-update reached VN_" + std::to_string(h) +
             " after its exchange-trigger of the same round";
    if (s[vns_[h].late_vn])
      return "(T2) a vn-update reached VN_" + std::to_string(h) +
             " after it computed the targets of the same round";
  }
  for (std::size_t i = 0; i < cns_.size(); ++i) {
    const CnSlots& cn = cns_[i];
    if (s[cn.late])
      return "(T3) a target-update reached CN_" + std::to_string(i) +
             " later than d_MMT + 2d_v after its target-trigger";
  }
  if (s[vns_[0].epoch] == this_round) // round 0: no VN is active yet (002:230)
    return std::nullopt;
  for (std::size_t i = 0; i < cns_.size(); ++i) {
    const CnSlots& cn = cns_[i];
    const bool round_start =
        !s[cn.failed] && s[cn.phase] == 0 && !s.is_bottom(cn.round) && s[cn.round] == this_round;
    if (!round_start)
      continue;
    if (s.is_bottom(cn.target) || s[cn.x] != s[cn.target])
      return "(T4) CN_" + std::to_string(i) + " is not on its target at a round start";
    const RegionId zone = lattice_.region_of(s[cn.x]);
    if (s[vns_[static_cast<std::size_t>(zone)].failed])
      return "(T4) VN_" + std::to_string(zone) + " is failed at a round start with CN_" +
             std::to_string(i) + " in its zone";
  }
  return std::nullopt;
}

std::optional<std::string> Observers::y_failure(const tioa::State& s) const {
  for (std::size_t f = 0; f < vns_.size(); ++f)
    for (std::size_t g = f + 1; g < vns_.size(); ++g) {
      const VnSlots &a = vns_[f], &b = vns_[g];
      if (s.is_bottom(a.y_round) || s.is_bottom(b.y_round) || s[a.y_round] != s[b.y_round] ||
          s[a.y_round] == older_round)
        continue;
      for (std::size_t j = 0; j < a.zones.size(); ++j)
        for (std::size_t k = 0; k < b.zones.size(); ++k)
          if (a.zones[j] == b.zones[k] && s[a.y[j]] != s[b.y[k]])
            return "(Y) VN_" + std::to_string(f) + " and VN_" + std::to_string(g) +
                   " computed the same round with y(" + std::to_string(a.zones[j]) +
                   ") = " + std::to_string(s[a.y[j]]) + " and " + std::to_string(s[b.y[k]]);
    }
  return std::nullopt;
}

std::optional<std::string> Observers::silent_cn(const tioa::State& s) const {
  for (std::size_t i = 0; i < cns_.size(); ++i) {
    const CnSlots& cn = cns_[i];
    if (s[cn.failed])
      continue;
    const std::pair<tioa::Variable<int>, const char*> counters[] = {
        {cn.round, "round"}, {cn.next_exch, "next-exch"}, {cn.next_target, "next-target"}};
    for (const auto& [counter, name] : counters)
      if (!s.is_bottom(counter) && s[counter] == past_round)
        return "(R) CN_" + std::to_string(i) + " is active with " + name +
               " in a past round: it never sends again (001 Fig. 2 lines 34-50)";
  }
  return std::nullopt;
}

bool Observers::overflowed(const tioa::State& s) const {
  if (s[channel_overflow_])
    return true;
  for (const VnSlots& vn : vns_)
    if (s[vn.overflow])
      return true;
  return false;
}

} // namespace vn_layer
