#include "models/vlayer_mc/lmc.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/rw.hpp"

namespace vlayer_mc {

std::uint64_t reset_family_size(const VlConfig& c) {
  const Lattice lattice = c.lattice();
  std::uint64_t n = std::uint64_t{1} << lattice.regions();
  for (int p = 0; p < c.robots; ++p)
    n *= 2 * static_cast<std::uint64_t>(lattice.points());
  return n;
}

std::string describe_reset_family(const VlConfig& c) {
  return std::to_string(reset_family_size(c)) +
         " ResetMC states built directly (every robot on every lattice point, its CN either "
         "unknown (x = ⊥) or standing on its target at phase 0; every VSA clock ⊥ or 0)";
}

tioa::StartSet reset_family(const VlConfig& c, const tioa::Automaton& layer) {
  const Lattice lattice = c.lattice();
  const int points = lattice.points(), regions = lattice.regions();
  const auto var = [&](const std::string& name) { return tioa::find_variable<int>(layer, name); };
  struct Robot {
    tioa::Variable<int> loc, vel, x, target, v, clock, reg;
  };
  std::vector<Robot> robots;
  for (int p = 0; p < c.robots; ++p) {
    const std::string cn = names::cn_name(p) + ".cn.", id = "[" + std::to_string(p) + "]";
    robots.push_back({var("RW.loc" + id), var("RW.vel" + id), var(cn + "x"), var(cn + "target"),
                      var(cn + "v"), var(cn + "clock"), var("VBcast.reg" + id)});
  }
  std::vector<tioa::Variable<int>> vsa_clocks;
  for (int u = 0; u < regions; ++u)
    vsa_clocks.push_back(var(names::vn_name(u) + ".clock"));

  // The family is built state by state as it is enumerated, never held whole: with three
  // robots on a 3x3 grid it has millions of states, and the explorer that takes them checks
  // its limits (time, memory, states) as they come.
  const std::uint32_t words = layer.words();
  auto initial = std::make_shared<std::vector<tioa::Word>>(words + 1, 0);
  tioa::State s(initial->data(), 0);
  for (const auto& v : layer.layout().variables())
    s.set_code(v.slot(), v.initial_code.value_or(0)); // Fail's `failed`: false
  const std::uint64_t count = reset_family_size(c);
  const std::uint32_t bits = layer.layout().bits();
  return tioa::StartSet(describe_reset_family(c), [=](tioa::Word* dst, std::uint32_t base,
                                                      const tioa::StartSet::Visit& visit) {
    std::vector<tioa::Word> buffer(initial->size());
    for (std::uint64_t index = 0; index < count; ++index) {
      std::copy(initial->begin(), initial->end(), buffer.begin());
      tioa::State t(buffer.data(), 0);
      std::uint64_t rest = index;
      for (const Robot& r : robots) {
        const int point = static_cast<int>(rest % static_cast<std::uint64_t>(points));
        rest /= static_cast<std::uint64_t>(points);
        const bool known = rest % 2 == 1;
        rest /= 2;
        t.set(r.loc, point);
        if (known) {
          t.set(r.x, point);
          t.set(r.target, point);
          t.set(r.v, zero_velocity);
          t.set(r.vel, zero_velocity);
          t.set(r.clock, 0);
          t.set(r.reg, lattice.region_of(point));
        }
      }
      for (const auto& clock : vsa_clocks) {
        if (rest % 2 == 1)
          t.set(clock, 0);
        rest /= 2;
      }
      tioa::copy_bits(dst, base, buffer.data(), 0, bits);
      visit();
    }
  });
}

} // namespace vlayer_mc
