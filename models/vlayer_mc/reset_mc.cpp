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

struct Node {
  std::string name;
  std::optional<tioa::Slot> failed;
  std::vector<tioa::Slot> empty; // must be false / ⊥ (to_send)
  std::optional<tioa::Slot> x, target, v;
};

} // namespace

ClauseCheck reset_mc_clauses(const VlConfig& c, const tioa::Automaton& layer, MWindow window) {
  const Lattice lattice = c.lattice();
  const ClauseCheck l1 = l1mc_clauses(c, layer, window);
  std::vector<Node> clients, vsas;
  std::vector<tioa::Slot> gps_age, pending;
  for (int p = 0; p < c.robots; ++p) {
    const std::string cn = names::cn_name(p), id = "[" + std::to_string(p) + "]";
    clients.push_back({cn,
                       find_slot(layer, cn + ".failed"),
                       {need_slot(layer, cn + ".delay.held", "ResetMC")},
                       need_slot(layer, cn + ".cn.x", "ResetMC"),
                       need_slot(layer, cn + ".cn.target", "ResetMC"),
                       need_slot(layer, cn + ".cn.v", "ResetMC")});
    // D31: the junk slots of the client's VBDelay are part of to_send_p^−.
    for (int j = 0;; ++j) {
      const auto kind = find_slot(layer, cn + ".delay.junk_kind[" + std::to_string(j) + "]");
      if (!kind)
        break;
      clients.back().empty.push_back(*kind);
    }
    gps_age.push_back(need_slot(layer, "RW.gps_age" + id, "ResetMC"));
    pending.push_back(need_slot(layer, "VBcast.cn_pending" + id, "ResetMC"));
  }
  for (int i = 0;; ++i) {
    const auto to = find_slot(layer, "VBcast.junk_to[" + std::to_string(i) + "]");
    if (!to)
      break;
    pending.push_back(*to);
  }
  for (int u = 0; u < lattice.regions(); ++u) {
    const std::string vn = names::vn_name(u);
    Node node{vn, find_slot(layer, vn + ".failed"), {}, {}, {}, {}};
    for (int p = 0; p < c.robots; ++p)
      node.empty.push_back(need_slot(layer, vn + ".out[" + std::to_string(p) + "]", "ResetMC"));
    vsas.push_back(node);
    pending.push_back(need_slot(layer, "VBcast.vn_mask[" + std::to_string(u) + "]", "ResetMC"));
    for (int p = 0; p < c.robots; ++p)
      pending.push_back(need_slot(
          layer, "VBcast.tu_pending[" + std::to_string(u * c.robots + p) + "]", "ResetMC"));
  }
  const tioa::Slot now = need_slot(layer, "RW.now", "ResetMC");

  return [=](const tioa::State& s) {
    std::vector<std::string> broken;
    for (const std::string& clause : l1(s))
      broken.push_back("(1) " + clause);
    const auto sending = [&](const tioa::Slot& slot) {
      return slot.has_bottom ? !is_bottom(s, slot) : s.code(slot) != 0;
    };
    for (const Node& cn : clients) {
      if (cn.failed && s.code(*cn.failed) != 0)
        continue;
      bool ok = std::none_of(cn.empty.begin(), cn.empty.end(), sending);
      if (!is_bottom(s, *cn.x))
        ok = ok && !is_bottom(s, *cn.target) && !is_bottom(s, *cn.v) &&
             value(s, *cn.v) == zero_velocity;
      if (!ok)
        broken.push_back("(2) " + cn.name);
    }
    for (const Node& vn : vsas) {
      if (vn.failed && s.code(*vn.failed) != 0)
        continue;
      for (const auto& slot : vn.empty)
        if (sending(slot)) {
          broken.push_back("(3) " + vn.name);
          break;
        }
    }
    for (const auto& slot : pending)
      if (s.code(slot) != 0) {
        broken.push_back("(4)");
        break;
      }
    bool fresh = value(s, now) == 0;
    for (const auto& age : gps_age)
      fresh = fresh && value(s, age) >= 1;
    if (!fresh)
      broken.push_back("(5)");
    return broken;
  };
}

tioa::StatePredicate reset_mc(const VlConfig& config, const tioa::Automaton& layer,
                              MWindow window) {
  const ClauseCheck clauses = reset_mc_clauses(config, layer, window);
  return [clauses](const tioa::State& s) { return clauses(s).empty(); };
}

tioa::StatePredicate reset_mc_or_targetless(const VlConfig& c, const tioa::Automaton& layer,
                                            MWindow window) {
  const ClauseCheck clauses = reset_mc_clauses(c, layer, window);
  struct Client {
    std::string clause; // "(2) CN_p"
    tioa::Slot held, x, target, v, since;
    std::vector<tioa::Slot> junk; // D31: the kinds of its VBDelay's junk slots
  };
  std::vector<Client> clients;
  for (int p = 0; p < c.robots; ++p) {
    const std::string cn = names::cn_name(p);
    const auto slot = [&](const std::string& name) { return need_slot(layer, cn + name, "D30"); };
    clients.push_back({"(2) " + cn,
                       slot(".delay.held"),
                       slot(".cn.x"),
                       slot(".cn.target"),
                       slot(".cn.v"),
                       slot(".cn.since"),
                       {}});
    for (int j = 0;; ++j) {
      const auto kind = find_slot(layer, cn + ".delay.junk_kind[" + std::to_string(j) + "]");
      if (!kind)
        break;
      clients.back().junk.push_back(*kind);
    }
  }
  return [=](const tioa::State& s) {
    for (const std::string& clause : clauses(s)) {
      // Only (2) CN_p may be broken, and only by a missing target while the cn-update is due
      // (clock_p = 0 by (1) and (5); `since` ≥ 1: not yet sent at this instant).
      const auto cn = std::find_if(clients.begin(), clients.end(),
                                   [&](const Client& client) { return client.clause == clause; });
      if (cn == clients.end())
        return false;
      const bool no_junk = std::all_of(cn->junk.begin(), cn->junk.end(),
                                       [&](const tioa::Slot& kind) { return s.code(kind) == 0; });
      const bool targetless = s.code(cn->held) == 0 && no_junk && !is_bottom(s, cn->x) &&
                              is_bottom(s, cn->target) && !is_bottom(s, cn->v) &&
                              value(s, cn->v) == zero_velocity && value(s, cn->since) >= 1;
      if (!targetless)
        return false;
    }
    return true;
  };
}

} // namespace vlayer_mc
