#include "models/vlayer_mc/l1mc.hpp"

#include <memory>
#include <optional>
#include <string_view>

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

// A node that breaks a clause: VN_index or CN_index.
struct BrokenNode {
  bool vn; // else a CN
  int index;
};

// Walks the clauses (2)–(4c) on a state, calling `broken(clause, node)` for each clause a
// node breaks (clause "(2)", node VN_1); stops at the first call that returns false. The
// predicate stops at the first broken clause (it reads no more than it needs, which keeps
// the zero-time reduction's dependencies on it small); the clause list does not.
class L1mcWalk {
public:
  L1mcWalk(const VlConfig& c, const tioa::Automaton& layer, MWindow window)
      : lattice_(c.lattice()), now_(need_slot(layer, "RW.now", "L1MC")), delta_(c.delta),
        target_phase_(c.target_phase()),
        window_end_(c.delta - c.d_r + c.eps_sample), // (4c), exclusive, may pass δ
        vmax_(c.vmax), d_r_(c.d_r), first_phase_(window == MWindow::closed ? 0 : 1) {
    for (int p = 0; p < c.robots; ++p) {
      const std::string cn = names::cn_name(p) + ".", id = "[" + std::to_string(p) + "]";
      clients_.push_back(
          {find_slot(layer, cn + "failed"), need_slot(layer, cn + "cn.clock", "L1MC"),
           need_slot(layer, cn + "cn.x", "L1MC"), need_slot(layer, cn + "cn.target", "L1MC"),
           need_slot(layer, cn + "cn.v", "L1MC"), need_slot(layer, "RW.vel" + id, "L1MC"),
           need_slot(layer, "RW.loc" + id, "L1MC"), need_slot(layer, "VBcast.reg" + id, "L1MC")});
    }
    for (int u = 0; u < lattice_.regions(); ++u) {
      const std::string vn = names::vn_name(u) + ".";
      VsaSlots slots{find_slot(layer, vn + "failed"), need_slot(layer, vn + "clock", "L1MC"), {}};
      for (int p = 0; p < c.robots; ++p)
        slots.M.push_back(need_slot(layer, vn + "M[" + std::to_string(p) + "]", "L1MC"));
      vsas_.push_back(slots);
    }
  }

  // Every clause of every node.
  template <class Broken> void operator()(const tioa::State& s, Broken&& broken) const {
    walk(s, broken, [](const char*, BrokenNode) { return true; });
  }

  // Only the clauses `wanted` selects, reading only what they need.
  template <class Broken, class Wanted>
  void walk(const tioa::State& s, Broken&& broken, Wanted&& wanted) const {
    std::optional<int> now;
    const auto time = [&] {
      if (!now)
        now = *read(s, now_);
      return *now;
    };
    if (!vsas_.empty() && wanted("(2)", BrokenNode{true, -1}))
      (void)time(); // (read first, as the walk always did)
    for (std::size_t u = 0; u < vsas_.size(); ++u) {
      const VsaSlots& vn = vsas_[u];
      if (!wanted("(2)", BrokenNode{true, static_cast<int>(u)}))
        continue;
      if (vn.failed && s.code(*vn.failed) != 0)
        continue;
      const auto clock = read(s, vn.clock);
      const bool clock_ok = !clock || *clock == time();
      bool heard = false;
      for (std::size_t m = 0; m < vn.M.size() && !heard; ++m)
        heard = read(s, vn.M[m]).has_value();
      const bool m_ok = !heard || (clock && *clock >= first_phase_ && *clock <= target_phase_);
      if ((!clock_ok || !m_ok) && !broken("(2)", BrokenNode{true, static_cast<int>(u)}))
        return;
    }
    for (std::size_t p = 0; p < clients_.size(); ++p) {
      const ClientSlots& cn = clients_[p];
      const BrokenNode who{false, static_cast<int>(p)};
      const bool want3 = wanted("(3)", who), want4a = wanted("(4a)", who),
                 want4b = wanted("(4b)", who), want4c = wanted("(4c)", who);
      if (!want3 && !want4a && !want4b && !want4c)
        continue;
      if (cn.failed && s.code(*cn.failed) != 0)
        continue;
      // (3) compares velocity vectors (D4, D27): "steer to q" is the vector of this quantum's
      // step from RW.loc(p), so steering to the point one stands on is the zero vector, and so
      // is RW.vel(p) = ⊥ (our RW moves a robot only towards a point, D8).
      const auto v = want3 ? read(s, cn.v) : std::nullopt;
      if (v) {
        const auto vel = read(s, cn.vel);
        const Point at = static_cast<Point>(*read(s, cn.loc));
        const auto step = [&](std::optional<int> steer) {
          return !steer || *steer == zero_velocity ? at : lattice_.step_toward(at, *steer, vmax_);
        };
        if (step(v) != step(vel) && !broken("(3)", who))
          return;
      }
      if (!want4a && !want4b && !want4c)
        continue;
      const auto x = read(s, cn.x);
      if (!x)
        continue;
      const auto clock = read(s, cn.clock);
      if (want4a && (*x != *read(s, cn.loc) || clock != time()) && !broken("(4a)", who))
        return;
      const auto target = want4b ? read(s, cn.target) : std::nullopt;
      if (target && *target != *x) {
        const int left = !clock || *clock == 0 ? 0 : delta_ - *clock; // δ⌈c/δ⌉ − c
        if (!(lattice_.distance(*target, *x) < vmax_ * (left - d_r_)) && !broken("(4b)", who))
          return;
      }
      if (!want4c)
        continue;
      const bool in_window = clock && ((*clock > target_phase_ && *clock < window_end_) ||
                                       *clock + delta_ < window_end_);
      if (in_window)
        continue;
      const auto reg = read(s, cn.reg);
      if (!(reg && *reg == lattice_.region_of(*x)) && !broken("(4c)", who))
        return;
    }
  }

private:
  Lattice lattice_;
  std::vector<ClientSlots> clients_;
  std::vector<VsaSlots> vsas_;
  tioa::Slot now_;
  int delta_, target_phase_, window_end_, vmax_, d_r_, first_phase_;
};

} // namespace

std::vector<tioa::StatePredicate> l1mc_conjuncts(const VlConfig& config,
                                                 const tioa::Automaton& layer, MWindow window) {
  const auto walk = std::make_shared<const L1mcWalk>(config, layer, window);
  std::vector<tioa::StatePredicate> conjuncts;
  const auto add = [&](const char* clause, BrokenNode node) {
    conjuncts.push_back([walk, clause, node](const tioa::State& s) {
      bool in = true;
      walk->walk(
          s,
          [&](const char*, BrokenNode) {
            in = false;
            return false;
          },
          // (index -1: any VN, as the walk asks before it reads RW.now for clause (2))
          [&](const char* c, BrokenNode n) {
            return std::string_view(c) == clause && n.vn == node.vn &&
                   (n.index == node.index || n.index < 0);
          });
      return in;
    });
  };
  for (int u = 0; u < config.lattice().regions(); ++u)
    add("(2)", BrokenNode{true, u});
  for (int p = 0; p < config.robots; ++p)
    for (const char* clause : {"(3)", "(4a)", "(4b)", "(4c)"})
      add(clause, BrokenNode{false, p});
  return conjuncts;
}

ClauseCheck l1mc_clauses(const VlConfig& c, const tioa::Automaton& layer, MWindow window) {
  return [walk = L1mcWalk(c, layer, window)](const tioa::State& s) {
    std::vector<std::string> broken;
    walk(s, [&](const char* clause, BrokenNode node) {
      broken.push_back(std::string(clause) + " " +
                       (node.vn ? names::vn_name(node.index) : names::cn_name(node.index)));
      return true;
    });
    return broken;
  };
}

tioa::StatePredicate l1mc(const VlConfig& config, const tioa::Automaton& layer, MWindow window) {
  return [walk = L1mcWalk(config, layer, window)](const tioa::State& s) {
    bool in = true;
    walk(s, [&](const char*, BrokenNode) {
      in = false;
      return false;
    });
    return in;
  };
}

} // namespace vlayer_mc
