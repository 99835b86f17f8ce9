#include "models/vlayer_mc/rw.hpp"

#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton rw(const VlConfig& c) {
  const Lattice lattice = c.lattice();
  const int n = c.robots, points = lattice.points();
  tioa::Automaton a("RW");
  const auto now = a.integer("now", 0, c.delta - 1, 0);
  const auto loc = a.integers("loc", n, 0, points - 1, std::nullopt);
  tioa::VariableArray<int> vel;
  for (int p = 0; p < n; ++p)
    vel.items.push_back(
        a.optional_integer("vel[" + std::to_string(p) + "]", zero_velocity, points - 1));
  const auto gps_age = a.clocks("gps_age", n, c.eps_sample, c.eps_sample);

  for (int p = 0; p < n; ++p) {
    a.output(names::gps_update(p), {{"l", 0, points - 1}, {"t", 0, c.delta - 1}})
        .pre([=](const State& s, const Params& x) {
          return s[gps_age[p]] >= 1 && x[0] == s[loc[p]] && x[1] == s[now];
        })
        .bind("l", loc[p])
        .bind("t", now)
        .eff([=](State& s, const Params&) { s[gps_age[p]] = 0; })
        .footprint([=](const Params&, tioa::Footprint& f) {
          f.reads(gps_age[p]).reads(loc[p]).reads(now).sets(gps_age[p], 0);
        });
    a.input(names::velocity(p), {{"v", zero_velocity, points - 1}})
        .eff([=](State& s, const Params& x) { s[vel[p]] = x[0]; })
        .footprint([=](const Params& x, tioa::Footprint& f) { f.sets(vel[p], x[0]); });
  }

  const int delta = c.delta, vmax = c.vmax, eps_sample = c.eps_sample;
  a.trajectories(
      [=](State& s) {
        s[now] = (s[now] + 1) % delta;
        for (int p = 0; p < n; ++p) {
          if (!s.is_bottom(vel[p]) && s[vel[p]] != zero_velocity)
            s[loc[p]] = lattice.step_toward(s[loc[p]], s[vel[p]], vmax);
          s.advance(gps_age[p]);
        }
      },
      [=](const State& s) {
        for (int p = 0; p < n; ++p)
          if (s[gps_age[p]] >= eps_sample)
            return true;
        return false;
      });
  return a;
}

} // namespace vlayer_mc
