#include "models/vlayer_mc/vbcast.hpp"

#include <algorithm>

#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vbcast(const VlConfig& c) {
  const Lattice lattice = c.lattice();
  const int n = c.robots, points = lattice.points(), regions = lattice.regions(), d = c.d;
  tioa::Automaton a("VBcast");
  tioa::VariableArray<int> reg;
  for (int p = 0; p < n; ++p)
    reg.items.push_back(a.optional_integer("reg[" + std::to_string(p) + "]", 0, regions - 1));
  const auto cn_pending = a.booleans("cn_pending", n, false);
  const auto cn_age = a.clocks("cn_age", n, d, 0);
  const auto cn_loc = a.integers("cn_loc", n, 0, points - 1, 0);
  tioa::VariableArray<int> vn_mask;
  for (int u = 0; u < regions; ++u) {
    const int bits = static_cast<int>(lattice.nbrs(u).size());
    vn_mask.items.push_back(a.integer("vn_mask[" + std::to_string(u) + "]", 0, (1 << bits) - 1, 0));
  }
  const auto vn_age = a.clocks("vn_age", regions, d, 0);
  const auto vn_count = a.integers("vn_count", regions, 0, n, 0);
  const auto tu_pending = a.booleans("tu_pending", regions * n, false);
  const auto tu_age = a.clocks("tu_age", regions * n, d, 0);
  const auto tu_target = a.integers("tu_target", regions * n, 0, points - 1, 0);

  for (int p = 0; p < n; ++p) {
    a.input(names::gps_update(p), {{"l", 0, points - 1}, {"t", 0, c.delta - 1}})
        .eff([=](State& s, const Params& x) { s[reg[p]] = lattice.region_of(x[0]); })
        .footprint(
            [=](const Params& x, tioa::Footprint& f) { f.sets(reg[p], lattice.region_of(x[0])); });
    a.input(names::vcast_prime_cn_update(p), {{"l", 0, points - 1}})
        .eff([=](State& s, const Params& x) {
          s[cn_pending[p]] =
              !s.is_bottom(reg[p]) && lattice.in_nbrs_plus(s[reg[p]], lattice.region_of(x[0]));
          s[cn_age[p]] = 0;
          s[cn_loc[p]] = x[0];
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.reads(reg[p]).writes(cn_pending[p]).sets(cn_age[p], 0).sets(cn_loc[p], x[0]);
        });
  }
  for (int u = 0; u < regions; ++u) {
    const auto& nbrs = lattice.nbrs(u);
    a.input(names::vcast_vn_update(u), {{"n", 0, n}})
        .eff([=](State& s, const Params& x) {
          s[vn_mask[u]] = (1 << nbrs.size()) - 1;
          s[vn_age[u]] = 0;
          s[vn_count[u]] = x[0];
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.sets(vn_mask[u], (1 << nbrs.size()) - 1).sets(vn_age[u], 0).sets(vn_count[u], x[0]);
        });
    a.input(names::vcast_target_update(u), {{"p", 0, n - 1}, {"x", 0, points - 1}})
        .eff([=](State& s, const Params& x) {
          const int slot = u * n + x[0];
          s[tu_pending[slot]] = !s.is_bottom(reg[x[0]]) && lattice.in_nbrs_plus(u, s[reg[x[0]]]);
          s[tu_age[slot]] = 0;
          s[tu_target[slot]] = x[1];
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          const int slot = u * n + x[0];
          f.reads(reg[x[0]]).writes(tu_pending[slot]).sets(tu_age[slot], 0);
          f.sets(tu_target[slot], x[1]);
        });
  }

  // Deliveries. A slot whose last receiver got the message is reset to age 0.
  for (int v = 0; v < regions; ++v) {
    a.output(names::vrcv_cn_update(v), {{"p", 0, n - 1}, {"l", 0, points - 1}})
        .pre([=](const State& s, const Params& x) {
          return s[cn_pending[x[0]]] && s[cn_loc[x[0]]] == x[1] && lattice.region_of(x[1]) == v;
        })
        .bind("l",
              [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
                return s[cn_loc[x[0]]];
              })
        .eff([=](State& s, const Params& x) {
          s[cn_pending[x[0]]] = false;
          s[cn_age[x[0]]] = 0;
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.reads(cn_pending[x[0]]).reads(cn_loc[x[0]]);
          f.sets(cn_pending[x[0]], false).sets(cn_age[x[0]], 0);
        });
    a.output(names::vrcv_vn_update(v), {{"g", 0, regions - 1}, {"n", 0, n}})
        .pre([=](const State& s, const Params& x) {
          const auto& from = lattice.nbrs(x[0]);
          const auto at = std::find(from.begin(), from.end(), v);
          return at != from.end() && (s[vn_mask[x[0]]] >> (at - from.begin()) & 1) != 0 &&
                 s[vn_count[x[0]]] == x[1];
        })
        .bind("n",
              [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
                return s[vn_count[x[0]]];
              })
        .eff([=](State& s, const Params& x) {
          const auto& from = lattice.nbrs(x[0]);
          const auto bit = std::find(from.begin(), from.end(), v) - from.begin();
          s[vn_mask[x[0]]] = s[vn_mask[x[0]]] & ~(1 << bit);
          if (s[vn_mask[x[0]]] == 0)
            s[vn_age[x[0]]] = 0;
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.reads(vn_mask[x[0]]).reads(vn_count[x[0]]);
          f.writes(vn_mask[x[0]]).sets(vn_age[x[0]], 0);
        });
  }
  for (int p = 0; p < n; ++p)
    a.output(names::vrcv_target_update(p), {{"u", 0, regions - 1}, {"x", 0, points - 1}})
        .pre([=](const State& s, const Params& x) {
          const int slot = x[0] * n + p;
          return s[tu_pending[slot]] && s[tu_target[slot]] == x[1];
        })
        .bind("x",
              [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
                return s[tu_target[x[0] * n + p]];
              })
        .eff([=](State& s, const Params& x) {
          const int slot = x[0] * n + p;
          s[tu_pending[slot]] = false;
          s[tu_age[slot]] = 0;
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          const int slot = x[0] * n + p;
          f.reads(tu_pending[slot]).reads(tu_target[slot]);
          f.sets(tu_pending[slot], false).sets(tu_age[slot], 0);
        });

  a.trajectories(
      [=](State& s) {
        for (int p = 0; p < n; ++p)
          if (s[cn_pending[p]])
            s.advance(cn_age[p]);
        for (int u = 0; u < regions; ++u)
          if (s[vn_mask[u]] != 0)
            s.advance(vn_age[u]);
        for (int slot = 0; slot < regions * n; ++slot)
          if (s[tu_pending[slot]])
            s.advance(tu_age[slot]);
      },
      [=](const State& s) {
        for (int p = 0; p < n; ++p)
          if (s[cn_pending[p]] && s[cn_age[p]] >= d)
            return true;
        for (int u = 0; u < regions; ++u)
          if (s[vn_mask[u]] != 0 && s[vn_age[u]] >= d)
            return true;
        for (int slot = 0; slot < regions * n; ++slot)
          if (s[tu_pending[slot]] && s[tu_age[slot]] >= d)
            return true;
        return false;
      });
  return a;
}

} // namespace vlayer_mc
