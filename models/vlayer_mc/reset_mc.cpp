#include "models/vlayer_mc/reset_mc.hpp"

#include <algorithm>

#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/slots.hpp"

namespace vlayer_mc {

namespace {

bool is_bottom(const tioa::State& s, const tioa::Slot& slot) {
  return slot.has_bottom && s.code(slot) == slot.value_codes;
}

std::int64_t value(const tioa::State& s, const tioa::Slot& slot) {
  return static_cast<std::int64_t>(s.code(slot)) + slot.lo;
}

// Whether a send buffer slot holds a message: not ⊥, or (without ⊥) not 0.
bool sending(const tioa::State& s, const tioa::Slot& slot) {
  return slot.has_bottom ? !is_bottom(s, slot) : s.code(slot) != 0;
}

struct Client {
  std::string name;
  std::optional<tioa::Slot> failed;
  std::vector<tioa::Slot> empty; // to_send_p^−: must hold nothing
  tioa::Slot x, target, v, since;
};

struct Vsa {
  std::string name;
  std::optional<tioa::Slot> failed;
  std::vector<tioa::Slot> out; // to_send_u: must be ⊥
};

// The variables clauses (2)–(5) read.
struct ResetSlots {
  std::vector<Client> clients;
  std::vector<Vsa> vsas;
  std::vector<tioa::Slot> gps_age, pending;
  tioa::Slot now;
};

ResetSlots reset_slots(const VlConfig& c, const tioa::Automaton& layer) {
  ResetSlots r;
  const auto slot = [&](const std::string& name) { return need_slot(layer, name, "ResetMC"); };
  for (int p = 0; p < c.robots; ++p) {
    const std::string cn = names::cn_name(p), id = "[" + std::to_string(p) + "]";
    r.clients.push_back({cn,
                         find_slot(layer, cn + ".failed"),
                         {slot(cn + ".delay.held")},
                         slot(cn + ".cn.x"),
                         slot(cn + ".cn.target"),
                         slot(cn + ".cn.v"),
                         slot(cn + ".cn.since")});
    // D31: the junk slots of the client's VBDelay are part of to_send_p^−.
    for (int j = 0;; ++j) {
      const auto kind = find_slot(layer, cn + ".delay.junk_kind[" + std::to_string(j) + "]");
      if (!kind)
        break;
      r.clients.back().empty.push_back(*kind);
    }
    r.gps_age.push_back(slot("RW.gps_age" + id));
    r.pending.push_back(slot("VBcast.cn_pending" + id));
  }
  for (int i = 0;; ++i) {
    const auto to = find_slot(layer, "VBcast.junk_to[" + std::to_string(i) + "]");
    if (!to)
      break;
    r.pending.push_back(*to);
  }
  for (int u = 0; u < c.lattice().regions(); ++u) {
    const std::string vn = names::vn_name(u);
    Vsa node{vn, find_slot(layer, vn + ".failed"), {}};
    for (int p = 0; p < c.robots; ++p)
      node.out.push_back(slot(vn + ".out[" + std::to_string(p) + "]"));
    r.vsas.push_back(node);
    r.pending.push_back(slot("VBcast.vn_mask[" + std::to_string(u) + "]"));
    for (int p = 0; p < c.robots; ++p)
      r.pending.push_back(slot("VBcast.tu_pending[" + std::to_string(u * c.robots + p) + "]"));
  }
  r.now = slot("RW.now");
  return r;
}

bool failed(const tioa::State& s, const std::optional<tioa::Slot>& flag) {
  return flag && s.code(*flag) != 0;
}

// Clause (2) for one client (met by a failed one).
bool client_reset(const tioa::State& s, const Client& cn) {
  if (failed(s, cn.failed))
    return true;
  bool ok = std::none_of(cn.empty.begin(), cn.empty.end(),
                         [&](const tioa::Slot& slot) { return sending(s, slot); });
  if (!is_bottom(s, cn.x))
    ok = ok && !is_bottom(s, cn.target) && !is_bottom(s, cn.v) && value(s, cn.v) == zero_velocity;
  return ok;
}

// D30: clause (2) broken only by a missing target while the cn-update is due (clock_p = 0 by
// (1) and (5); `since` ≥ 1: not yet sent at this instant).
bool client_targetless(const tioa::State& s, const Client& cn) {
  return std::none_of(cn.empty.begin(), cn.empty.end(),
                      [&](const tioa::Slot& slot) { return sending(s, slot); }) &&
         !is_bottom(s, cn.x) && is_bottom(s, cn.target) && !is_bottom(s, cn.v) &&
         value(s, cn.v) == zero_velocity && value(s, cn.since) >= 1;
}

// Clause (3) for one VSA (met by a failed one).
bool vsa_reset(const tioa::State& s, const Vsa& vn) {
  return failed(s, vn.failed) ||
         std::none_of(vn.out.begin(), vn.out.end(),
                      [&](const tioa::Slot& slot) { return sending(s, slot); });
}

// Clause (5).
bool fresh(const tioa::State& s, const ResetSlots& r) {
  return value(s, r.now) == 0 &&
         std::all_of(r.gps_age.begin(), r.gps_age.end(),
                     [&](const tioa::Slot& age) { return value(s, age) >= 1; });
}

} // namespace

ClauseCheck reset_mc_clauses(const VlConfig& c, const tioa::Automaton& layer, MWindow window) {
  const ClauseCheck l1 = l1mc_clauses(c, layer, window);
  const ResetSlots r = reset_slots(c, layer);
  return [l1, r](const tioa::State& s) {
    std::vector<std::string> broken;
    for (const std::string& clause : l1(s))
      broken.push_back("(1) " + clause);
    for (const Client& cn : r.clients)
      if (!client_reset(s, cn))
        broken.push_back("(2) " + cn.name);
    for (const Vsa& vn : r.vsas)
      if (!vsa_reset(s, vn))
        broken.push_back("(3) " + vn.name);
    if (std::any_of(r.pending.begin(), r.pending.end(),
                    [&](const tioa::Slot& slot) { return s.code(slot) != 0; }))
      broken.push_back("(4)");
    if (!fresh(s, r))
      broken.push_back("(5)");
    return broken;
  };
}

tioa::StatePredicate reset_mc(const VlConfig& config, const tioa::Automaton& layer,
                              MWindow window) {
  const ClauseCheck clauses = reset_mc_clauses(config, layer, window);
  return [clauses](const tioa::State& s) { return clauses(s).empty(); };
}

std::vector<tioa::StatePredicate>
reset_mc_or_targetless_conjuncts(const VlConfig& c, const tioa::Automaton& layer, MWindow window) {
  std::vector<tioa::StatePredicate> conjuncts = l1mc_conjuncts(c, layer, window);
  const ResetSlots r = reset_slots(c, layer);
  for (const Client& cn : r.clients)
    conjuncts.push_back(
        [cn](const tioa::State& s) { return client_reset(s, cn) || client_targetless(s, cn); });
  for (const Vsa& vn : r.vsas)
    conjuncts.push_back([vn](const tioa::State& s) { return vsa_reset(s, vn); });
  for (const tioa::Slot& slot : r.pending)
    conjuncts.push_back([slot](const tioa::State& s) { return s.code(slot) == 0; });
  conjuncts.push_back([r](const tioa::State& s) { return fresh(s, r); });
  return conjuncts;
}

tioa::StatePredicate reset_mc_or_targetless(const VlConfig& c, const tioa::Automaton& layer,
                                            MWindow window) {
  const tioa::StatePredicate l1 = l1mc(c, layer, window);
  const ResetSlots r = reset_slots(c, layer);
  return [l1, r](const tioa::State& s) {
    return l1(s) &&
           std::all_of(
               r.clients.begin(), r.clients.end(),
               [&](const Client& cn) { return client_reset(s, cn) || client_targetless(s, cn); }) &&
           std::all_of(r.vsas.begin(), r.vsas.end(),
                       [&](const Vsa& vn) { return vsa_reset(s, vn); }) &&
           std::none_of(r.pending.begin(), r.pending.end(),
                        [&](const tioa::Slot& slot) { return s.code(slot) != 0; }) &&
           fresh(s, r);
  };
}

} // namespace vlayer_mc
