#include "models/vlayer_mc/vbdelay.hpp"

#include <algorithm>

#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vbdelay(const VlConfig& c, int p) {
  const int points = c.lattice().points(), e = c.e;
  tioa::Automaton a("delay");
  const auto held = a.boolean("held", false);
  const auto age = a.clock("age", std::max(e, 1), 0);
  const auto loc = a.integer("loc", 0, points - 1, 0);
  a.input(names::vcast_cn_update(p), {{"l", 0, points - 1}})
      .eff([=](State& s, const Params& x) {
        s[held] = true;
        s[age] = 0;
        s[loc] = x[0];
      })
      .footprint([=](const Params& x, tioa::Footprint& f) {
        f.sets(held, true).sets(age, 0).sets(loc, x[0]);
      });
  a.output(names::vcast_prime_cn_update(p), {{"l", 0, points - 1}})
      .pre([=](const State& s, const Params& x) { return s[held] && x[0] == s[loc]; })
      .bind("l", loc)
      .eff([=](State& s, const Params&) {
        s[held] = false;
        s[age] = 0;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(held).reads(loc).sets(held, false).sets(age, 0);
      });
  a.trajectories(
      [=](State& s) {
        if (s[held])
          s.advance(age);
      },
      [=](const State& s) { return s[held] && s[age] >= e; });
  return a;
}

} // namespace vlayer_mc
