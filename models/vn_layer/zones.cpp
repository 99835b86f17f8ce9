#include "models/vn_layer/zones.hpp"

#include "models/vn_layer/names.hpp"

namespace vn_layer {

using tioa::Params;
using tioa::State;

tioa::Automaton zones(const VnConfig& c) {
  const Lattice lattice = c.lattice();
  const int n = c.cns, regions = lattice.regions(), d_r = c.d_r;
  tioa::Automaton a("Zones");
  const auto zone = a.integers("zone", n, 0, regions - 1, std::nullopt);
  const auto active = a.booleans("active", n, true);
  const auto vn_failed = a.booleans("vn_failed", regions, c.vns_start_failed);
  const auto occupied_for = a.clocks("occupied_for", regions, d_r, 0);

  const auto occupied = [=](const State& s, int h) {
    for (int i = 0; i < n; ++i)
      if (s[active[i]] && s[zone[i]] == h)
        return true;
    return false;
  };
  // What `occupied` reads.
  const auto reads_occupancy = [=](tioa::Footprint& f) {
    for (int i = 0; i < n; ++i)
      f.reads(active[i]).reads(zone[i]);
  };
  // A zone that has lost its last active CN starts counting again from 0.
  const auto restart_counts = [=](State& s) {
    for (int h = 0; h < regions; ++h)
      if (!occupied(s, h))
        s[occupied_for[h]] = 0;
  };
  for (int i = 0; i < n; ++i) {
    a.input(names::enter(i), {{"h", 0, regions - 1}})
        .eff([=](State& s, const Params& m) {
          s[zone[i]] = m[0];
          restart_counts(s);
        })
        .footprint([=](const Params& m, tioa::Footprint& f) {
          reads_occupancy(f);
          f.sets(zone[i], m[0]);
          for (int h = 0; h < regions; ++h)
            f.sets(occupied_for[h], 0);
        });
    a.input(names::fail_cn(i)).eff([=](State& s, const Params&) {
      s[active[i]] = false;
      restart_counts(s);
    });
    a.input(names::recover_cn(i)).eff([=](State& s, const Params&) { s[active[i]] = true; });
  }
  const VnFail policy = c.vn_fail;
  for (int h = 0; h < regions; ++h) {
    // C10: fail_h is an input of the layer with no stated condition; vn_fail reads it.
    a.output(names::fail_vn(h))
        .pre([=](const State& s, const Params&) {
          return !s[vn_failed[h]] &&
                 (policy == VnFail::any || (policy == VnFail::empty && !occupied(s, h)));
        })
        .eff([=](State& s, const Params&) {
          s[vn_failed[h]] = true;
          s[occupied_for[h]] = 0; // the d_r of C9 counts from the failure
        })
        .footprint([=](const Params&, tioa::Footprint& f) {
          reads_occupancy(f);
          f.reads(vn_failed[h]).sets(vn_failed[h], true).sets(occupied_for[h], 0);
        });
    // C9: "If VN_h is failed and a CN is in B_h and remains active in the zone for d_r
    // time, then a recover_h occurs within that d_r time" (002:83).
    a.output(names::recover_vn(h))
        .pre([=](const State& s, const Params&) { return s[vn_failed[h]] && occupied(s, h); })
        .eff([=](State& s, const Params&) { s[vn_failed[h]] = false; })
        .footprint([=](const Params&, tioa::Footprint& f) {
          reads_occupancy(f);
          f.reads(vn_failed[h]).sets(vn_failed[h], false);
        });
  }
  a.trajectories(
      [=](State& s) {
        for (int h = 0; h < regions; ++h)
          if (occupied(s, h))
            s.advance(occupied_for[h]);
      },
      [=](const State& s) {
        for (int h = 0; h < regions; ++h)
          if (s[vn_failed[h]] && occupied(s, h) && s[occupied_for[h]] >= d_r)
            return true;
        return false;
      });
  return a;
}

tioa::Automaton client_faults(const VnConfig& c, bool cn_faults) {
  tioa::Automaton a("ClientFaults");
  for (int i = 0; i < c.cns; ++i)
    for (const std::string& action : {names::fail_cn(i), names::recover_cn(i)})
      a.output(action)
          .pre([=](const State&, const Params&) { return cn_faults; })
          .footprint([](const Params&, tioa::Footprint&) {});
  return a;
}

} // namespace vn_layer
