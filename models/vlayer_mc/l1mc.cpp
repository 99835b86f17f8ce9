#include "models/vlayer_mc/l1mc.hpp"

#include <optional>

#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/slots.hpp"

namespace vlayer_mc {

namespace {

// A slot's value, nullopt for ⊥.
std::optional<int> read(const tioa::State& s, const tioa::Slot& slot) {
  const std::uint64_t code = s.code(slot);
  if (slot.has_bottom && code == slot.value_codes)
    return std::nullopt;
  return static_cast<int>(static_cast<std::int64_t>(code) + slot.lo);
}

struct ClientSlots {
  std::optional<tioa::Slot> failed;
  tioa::Slot clock, x, target, v, vel, loc, reg;
};

struct VsaSlots {
  std::optional<tioa::Slot> failed;
  tioa::Slot clock;
  std::vector<tioa::Slot> M;
};

} // namespace

ClauseCheck l1mc_clauses(const VlConfig& c, const tioa::Automaton& layer, MWindow window) {
  const Lattice lattice = c.lattice();
  std::vector<ClientSlots> clients;
  for (int p = 0; p < c.robots; ++p) {
    const std::string cn = names::cn_name(p) + ".", id = "[" + std::to_string(p) + "]";
    clients.push_back(
        {find_slot(layer, cn + "failed"), need_slot(layer, cn + "cn.clock", "L1MC"),
         need_slot(layer, cn + "cn.x", "L1MC"), need_slot(layer, cn + "cn.target", "L1MC"),
         need_slot(layer, cn + "cn.v", "L1MC"), need_slot(layer, "RW.vel" + id, "L1MC"),
         need_slot(layer, "RW.loc" + id, "L1MC"), need_slot(layer, "VBcast.reg" + id, "L1MC")});
  }
  std::vector<VsaSlots> vsas;
  for (int u = 0; u < lattice.regions(); ++u) {
    const std::string vn = names::vn_name(u) + ".";
    VsaSlots slots{find_slot(layer, vn + "failed"), need_slot(layer, vn + "clock", "L1MC"), {}};
    for (int p = 0; p < c.robots; ++p)
      slots.M.push_back(need_slot(layer, vn + "M[" + std::to_string(p) + "]", "L1MC"));
    vsas.push_back(slots);
  }
  const tioa::Slot now = need_slot(layer, "RW.now", "L1MC");
  const int delta = c.delta, target_phase = c.target_phase();
  const int window_end = c.delta - c.d_r + c.eps_sample; // (4c), exclusive, may pass δ
  const int vmax = c.vmax, d_r = c.d_r;
  const int first_phase = window == MWindow::closed ? 0 : 1;

  return [=](const tioa::State& s) {
    std::vector<std::string> broken;
    const int time = *read(s, now);
    for (std::size_t u = 0; u < vsas.size(); ++u) {
      const VsaSlots& vn = vsas[u];
      if (vn.failed && s.code(*vn.failed) != 0)
        continue;
      const auto clock = read(s, vn.clock);
      bool heard = false;
      for (const auto& m : vn.M)
        heard |= read(s, m).has_value();
      const bool clock_ok = !clock || *clock == time;
      const bool m_ok = !heard || (clock && *clock >= first_phase && *clock <= target_phase);
      if (!clock_ok || !m_ok)
        broken.push_back("(2) " + names::vn_name(static_cast<int>(u)));
    }
    for (std::size_t p = 0; p < clients.size(); ++p) {
      const ClientSlots& cn = clients[p];
      const std::string who = " " + names::cn_name(static_cast<int>(p));
      if (cn.failed && s.code(*cn.failed) != 0)
        continue;
      // (3) compares velocity vectors (D4, D27): "steer to q" is the vector of this quantum's
      // step from RW.loc(p), so steering to the point one stands on is the zero vector, and so
      // is RW.vel(p) = ⊥ (our RW moves a robot only towards a point, D8).
      const auto v = read(s, cn.v), vel = read(s, cn.vel);
      const Point at = static_cast<Point>(*read(s, cn.loc));
      const auto step = [&](std::optional<int> steer) {
        return !steer || *steer == zero_velocity ? at : lattice.step_toward(at, *steer, vmax);
      };
      if (v && step(v) != step(vel))
        broken.push_back("(3)" + who);
      const auto x = read(s, cn.x);
      if (!x)
        continue;
      const auto clock = read(s, cn.clock);
      if (*x != *read(s, cn.loc) || clock != time)
        broken.push_back("(4a)" + who);
      const auto target = read(s, cn.target);
      if (target && *target != *x) {
        const int left = !clock || *clock == 0 ? 0 : delta - *clock; // δ⌈c/δ⌉ − c
        if (!(lattice.distance(*target, *x) < vmax * (left - d_r)))
          broken.push_back("(4b)" + who);
      }
      const auto reg = read(s, cn.reg);
      const bool in_window =
          clock && ((*clock > target_phase && *clock < window_end) || *clock + delta < window_end);
      if (!(reg && *reg == lattice.region_of(*x)) && !in_window)
        broken.push_back("(4c)" + who);
    }
    return broken;
  };
}

tioa::StatePredicate l1mc(const VlConfig& config, const tioa::Automaton& layer, MWindow window) {
  const ClauseCheck clauses = l1mc_clauses(config, layer, window);
  return [clauses](const tioa::State& s) { return clauses(s).empty(); };
}

} // namespace vlayer_mc
