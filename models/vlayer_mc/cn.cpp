#include "models/vlayer_mc/cn.hpp"

#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/rw.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton cn(const VlConfig& c, int p) {
  const Lattice lattice = c.lattice();
  const int points = lattice.points();
  tioa::Automaton a("cn");
  const auto clock = a.optional_integer("clock", 0, c.delta - 1);
  const auto x = a.optional_integer("x", 0, points - 1);
  const auto target = a.optional_integer("target", 0, points - 1);
  const auto v = a.optional_integer("v", zero_velocity, points - 1);
  const auto since = a.clock("since", 1, 1);

  // D5: 0 without a position or a target, or on the target; else steer to the target.
  const auto desired = [=](const State& s) {
    if (s.is_bottom(x) || s.is_bottom(target) || s[x] == s[target])
      return zero_velocity;
    return static_cast<int>(s[target]);
  };
  const auto velocity_due = [=](const State& s) { return s.is_bottom(v) || s[v] != desired(s); };
  // Def 7.1(4b): x* = x, or x* lies nearer than v_max(δ⌈clock/δ⌉ − clock − d_r).
  const int delta_rule = c.delta, vmax_rule = c.vmax, d_r = c.d_r;
  const bool filter = c.filter_targets, repair = c.cn_repair;
  const int target_phase = c.target_phase(), arrival = c.d;
  const auto reachable = [=](Point at, Point goal, int phase) {
    const int left = phase == 0 ? 0 : delta_rule - phase;
    return goal == at || lattice.distance(goal, at) < vmax_rule * (left - d_r);
  };
  const auto cn_update_due = [=](const State& s) {
    return !s.is_bottom(clock) && s[clock] == 0 && s[since] >= 1 && !s.is_bottom(x);
  };

  a.input(names::gps_update(p), {{"l", 0, points - 1}, {"t", 0, c.delta - 1}})
      .eff([=](State& s, const Params& m) {
        // The paper: the CN records its position and the time.
        if (!repair) {
          s[x] = m[0];
          s[clock] = m[1];
          return;
        }
        // D25 (cn_repair) self-stabilisation: a CN whose view was wrong (position or clock)
        // no longer knows its velocity (v := ⊥, so the stop-when condition outputs a velocity
        // at once) nor trusts its target (taken under the wrong view: x* := ⊥), and a target
        // it cannot reach in this round (Def 7.1(4b)) is dropped. On every state reachable
        // without failures these are no-ops: the view is right and (4b) holds.
        const bool wrong = (!s.is_bottom(x) && (s[x] != m[0] || s.is_bottom(clock))) ||
                           (!s.is_bottom(clock) && s[clock] != m[1]);
        const bool fresh = s.is_bottom(x); // a target before its first position is stale
        s[x] = m[0];
        s[clock] = m[1];
        if (wrong)
          s.set_bottom(v);
        if (wrong || fresh)
          s.set_bottom(target);
        if (!s.is_bottom(target) && !reachable(m[0], s[target], m[1]))
          s.set_bottom(target);
      })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.sets(x, m[0]).sets(clock, m[1]);
        if (repair)
          f.reads(x).reads(clock).reads(target).sets_bottom(v).sets_bottom(target);
      });
  a.output(names::vcast_cn_update(p), {{"l", 0, points - 1}})
      .pre([=](const State& s, const Params& m) { return cn_update_due(s) && m[0] == s[x]; })
      .bind("l", x)
      .eff([=](State& s, const Params&) {
        s[since] = 0;
        s.set_bottom(target);
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(clock).reads(since).reads(x).sets(since, 0).sets_bottom(target);
      });
  a.input(names::vrcv_target_update(p), {{"u", 0, lattice.regions() - 1}, {"x", 0, points - 1}})
      .eff([=](State& s, const Params& m) {
        // D28: targets are computed at e + 2d + 2ε and VBcast takes up to d; without a
        // position and a clock a CN cannot tell.
        if (filter && (s.is_bottom(x) || s.is_bottom(clock) || s[clock] < target_phase ||
                       s[clock] > target_phase + arrival || !reachable(s[x], m[1], s[clock])))
          return;
        s[target] = m[1];
      })
      .footprint(
          [=](const Params& m, tioa::Footprint& f) { f.reads(x).reads(clock).sets(target, m[1]); });
  a.output(names::velocity(p), {{"v", zero_velocity, points - 1}})
      .pre([=](const State& s, const Params& m) { return velocity_due(s) && m[0] == desired(s); })
      .bind(
          "v",
          [=](const State& s, const Params&) -> std::optional<std::int32_t> { return desired(s); })
      .eff([=](State& s, const Params& m) { s[v] = m[0]; })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.reads(v).reads(x).reads(target).sets(v, m[0]);
      });

  const int delta = c.delta, vmax = c.vmax;
  a.trajectories(
      [=](State& s) {
        if (!s.is_bottom(clock))
          s[clock] = (s[clock] + 1) % delta;
        s.advance(since);
        if (!s.is_bottom(x) && !s.is_bottom(v) && s[v] != zero_velocity)
          s[x] = lattice.step_toward(s[x], s[v], vmax);
      },
      [=](const State& s) { return cn_update_due(s) || velocity_due(s); });
  return a;
}

} // namespace vlayer_mc
