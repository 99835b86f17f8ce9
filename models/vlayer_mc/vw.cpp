#include "models/vlayer_mc/vw.hpp"

#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vw(const VlConfig& c, bool vsa_faults) {
  const int regions = c.lattice().regions();
  tioa::Automaton a("VW");
  const auto now = a.integer("now", 0, c.delta - 1, 0);
  const auto age = a.clocks("age", regions, c.eps_sample, c.eps_sample);
  for (int u = 0; u < regions; ++u) {
    a.output(names::time(u), {{"t", 0, c.delta - 1}})
        .pre([=](const State& s, const Params& x) { return s[age[u]] >= 1 && x[0] == s[now]; })
        .bind("t", now)
        .eff([=](State& s, const Params&) { s[age[u]] = 0; })
        .footprint(
            [=](const Params&, tioa::Footprint& f) { f.reads(age[u]).reads(now).sets(age[u], 0); });
    // VW owns fail_u and restart_u (line 577). Without vsa_faults they are outputs that are
    // never enabled, so Fail(VN_u)'s inputs are closed and never fire (finding F2).
    for (const std::string& action : {names::fail_vn(u), names::restart_vn(u)})
      a.output(action)
          .pre([=](const State&, const Params&) { return vsa_faults; })
          .footprint([](const Params&, tioa::Footprint&) {});
  }
  const int delta = c.delta, eps_sample = c.eps_sample;
  a.trajectories(
      [=](State& s) {
        s[now] = (s[now] + 1) % delta;
        for (int u = 0; u < regions; ++u)
          s.advance(age[u]);
      },
      [=](const State& s) {
        for (int u = 0; u < regions; ++u)
          if (s[age[u]] >= eps_sample)
            return true;
        return false;
      });
  return a;
}

} // namespace vlayer_mc
