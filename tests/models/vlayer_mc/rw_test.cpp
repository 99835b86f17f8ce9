// RW (seed 000 §4.1) on hand-made states: GPSupdate, the velocity signal, and time.
#include <catch2/catch.hpp>

#include "models/vlayer_mc/rw.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;

TEST_CASE("vlayer RW: a GPSupdate every eps_sample, with the true place and time", "[vlayer]") {
  const vlayer_mc::VlConfig c; // 1×2, b 2, δ 6, eps_sample 1, vmax 4
  const auto rw = vlayer_mc::rw(c);
  Words s = start(rw);
  CHECK(get(rw, s, "now") == 0);
  CHECK_FALSE(get(rw, s, "vel[0]"));
  set(rw, s, "loc[0]", 6);
  auto all = steps(rw, s);
  CHECK_FALSE(has(all, "tick")); // the first update is due at time 0
  CHECK(only(all, "GPSupdate_0").size() == 1);
  CHECK(has(all, "GPSupdate_0(6,0)"));
  s = after(rw, s, "GPSupdate_0(6,0)");
  CHECK(get(rw, s, "gps_age[0]") == 0);
  all = steps(rw, s);
  CHECK(only(all, "GPSupdate_0").empty()); // at most one per instant
  CHECK(has(all, "tick"));
  s = after(rw, s, "tick");
  CHECK(get(rw, s, "now") == 1);
  CHECK_FALSE(has(steps(rw, s), "tick"));
}

TEST_CASE("vlayer RW: robots move towards the point they steer to (D4, D8)", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.vmax = 1;
  c.eps_sample = 3;
  const auto rw = vlayer_mc::rw(c);
  Words s = start(rw);
  set(rw, s, "loc[0]", 5);     // (0, 1)
  set(rw, s, "gps_age[0]", 0); // just updated
  set(rw, s, "now", 5);
  s = after(rw, s, "velocity_0(8)"); // steer to (3, 1)
  CHECK(get(rw, s, "vel[0]") == 8);
  s = after(rw, s, "tick");
  CHECK(get(rw, s, "now") == 0); // modulo δ (D15)
  CHECK(get(rw, s, "loc[0]") == 6);
  s = after(rw, s, "velocity_0(-1)"); // velocity 0
  s = after(rw, s, "tick");
  CHECK(get(rw, s, "loc[0]") == 6);
}
