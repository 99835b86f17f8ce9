#include "models/vlayer_mc/vw.hpp"

#include <algorithm>

#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vw(const VlConfig& c, bool vsa_faults) {
  const Lattice lattice = c.lattice();
  const int regions = lattice.regions(), points = lattice.points();
  tioa::Automaton a("VW");
  const auto now = a.integer("now", 0, c.delta - 1, 0);
  const auto age = a.clocks("age", regions, c.eps_sample, c.eps_sample);

  // D32, the d_r rule (seed 000 §7, lines 1176–1178), with dr_rule only: what VW knows of
  // the clients, from their GPSupdates and their fail and restart actions.
  const bool rule = c.dr_rule;
  const int robots = rule ? c.robots : 0, rule_regions = rule ? regions : 0, d_r = c.d_r;
  tioa::VariableArray<int> where;
  for (int p = 0; p < robots; ++p)
    where.items.push_back(
        a.optional_integer("client_region[" + std::to_string(p) + "]", 0, regions - 1));
  const auto up = a.booleans("client_up", robots, true);
  const auto stay = a.clocks("stay", robots, std::max(d_r, 1), 0);
  const auto calm = a.clocks("calm", rule_regions, std::max(d_r, 1), std::max(d_r, 1));
  const auto kept = a.booleans("kept", rule_regions, false);
  // C_u: a live client has been in u for d_r, and no live client failed in u or left it in
  // that time.
  const auto settled = [=](const State& s, int u) {
    if (s[calm[u]] < d_r)
      return false;
    for (int p = 0; p < robots; ++p)
      if (s[up[p]] && !s.is_bottom(where[p]) && s[where[p]] == u && s[stay[p]] >= d_r)
        return true;
    return false;
  };
  // A live client failed in u or left it: C_u starts again.
  const auto disturb = [=](State& s, int u) {
    s[calm[u]] = 0;
    s[kept[u]] = false;
  };
  const auto rule_footprint = [=](tioa::Footprint& f) {
    for (int p = 0; p < robots; ++p)
      f.reads(where[p]).reads(up[p]).reads(stay[p]).writes(where[p]).writes(up[p]).writes(stay[p]);
    for (int u = 0; u < rule_regions; ++u)
      f.reads(calm[u]).reads(kept[u]).writes(calm[u]).writes(kept[u]);
  };

  for (int p = 0; p < robots; ++p) {
    a.input(names::gps_update(p), {{"l", 0, points - 1}, {"t", 0, c.delta - 1}})
        .eff([=](State& s, const Params& x) {
          const int r = lattice.region_of(x[0]);
          if (!s.is_bottom(where[p]) && s[where[p]] == r)
            return;
          if (s[up[p]] && !s.is_bottom(where[p]))
            disturb(s, s[where[p]]);
          s[where[p]] = r;
          s[stay[p]] = 0;
        })
        .footprint([=](const Params&, tioa::Footprint& f) { rule_footprint(f); });
    a.input(names::fail_cn(p))
        .eff([=](State& s, const Params&) {
          if (s[up[p]] && !s.is_bottom(where[p]))
            disturb(s, s[where[p]]);
          s[up[p]] = false;
          s[stay[p]] = 0;
        })
        .footprint([=](const Params&, tioa::Footprint& f) { rule_footprint(f); });
    a.input(names::restart_cn(p))
        .eff([=](State& s, const Params&) {
          if (!s[up[p]]) {
            s[up[p]] = true;
            s[stay[p]] = 0;
          }
        })
        .footprint([=](const Params&, tioa::Footprint& f) { rule_footprint(f); });
  }

  for (int u = 0; u < regions; ++u) {
    a.output(names::time(u), {{"t", 0, c.delta - 1}})
        .pre([=](const State& s, const Params& x) { return s[age[u]] >= 1 && x[0] == s[now]; })
        .bind("t", now)
        .eff([=](State& s, const Params&) { s[age[u]] = 0; })
        .footprint(
            [=](const Params&, tioa::Footprint& f) { f.reads(age[u]).reads(now).sets(age[u], 0); });
    // VW owns fail_u and restart_u (line 577). Without vsa_faults (and the d_r rule) they are
    // outputs that are never enabled, so Fail(VN_u)'s inputs are closed and never fire
    // (finding F2). D32: with the rule, VW never fails VN_u while C_u holds, and restarts
    // it once when C_u begins (a restart of a live VSA changes nothing, tioa/fail.hpp).
    a.output(names::fail_vn(u))
        .pre([=](const State& s, const Params&) { return vsa_faults && !(rule && settled(s, u)); })
        .footprint([=](const Params&, tioa::Footprint& f) { rule_footprint(f); });
    a.output(names::restart_vn(u))
        .pre([=](const State& s, const Params&) {
          return vsa_faults || (rule && settled(s, u) && !s[kept[u]]);
        })
        .eff([=](State& s, const Params&) {
          if (rule && settled(s, u))
            s[kept[u]] = true;
        })
        .footprint([=](const Params&, tioa::Footprint& f) { rule_footprint(f); });
  }
  const int delta = c.delta, eps_sample = c.eps_sample;
  a.trajectories(
      [=](State& s) {
        s[now] = (s[now] + 1) % delta;
        for (int u = 0; u < regions; ++u)
          s.advance(age[u]);
        for (int p = 0; p < robots; ++p)
          if (s[up[p]] && !s.is_bottom(where[p]))
            s.advance(stay[p]);
        for (int u = 0; u < rule_regions; ++u)
          s.advance(calm[u]);
      },
      [=](const State& s) {
        for (int u = 0; u < regions; ++u)
          if (s[age[u]] >= eps_sample)
            return true;
        for (int u = 0; u < rule_regions; ++u)
          if (settled(s, u) && !s[kept[u]])
            return true;
        return false;
      });
  return a;
}

} // namespace vlayer_mc
