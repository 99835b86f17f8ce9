// VW and VBDelay (seed 000 §4.1) on hand-made states.
#include <catch2/catch.hpp>

#include "models/vlayer_mc/vbdelay.hpp"
#include "models/vlayer_mc/vw.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;

TEST_CASE("vlayer VW: time(t)_u at time 0 and every eps_sample; VSA faults", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.eps_sample = 2;
  const auto vw = vlayer_mc::vw(c, false);
  Words s = start(vw);
  auto all = steps(vw, s);
  CHECK_FALSE(has(all, "tick"));
  CHECK(has(all, "time_0(0)"));
  CHECK(has(all, "time_1(0)"));
  CHECK_FALSE(has(all, "time_0(1)"));
  CHECK(only(all, "fail_").empty());
  s = after(vw, after(vw, s, "time_0(0)"), "time_1(0)");
  s = after(vw, s, "tick");
  CHECK(get(vw, s, "now") == 1);
  CHECK(has(steps(vw, s), "tick")); // the next update is due only at age 2
  s = after(vw, s, "tick");
  CHECK_FALSE(has(steps(vw, s), "tick"));
  CHECK(has(steps(vw, s), "time_1(2)"));

  const auto faulty = vlayer_mc::vw(c, true);
  CHECK(has(steps(faulty, start(faulty)), "fail_VN_1"));
  CHECK(has(steps(faulty, start(faulty)), "restart_VN_0"));
}

TEST_CASE("vlayer VBDelay: a cn-update is handed to VBcast within e", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.e = 1;
  const auto delay = vlayer_mc::vbdelay(c, 0);
  Words s = start(delay);
  CHECK(only(steps(delay, s), "vcast'_").empty());
  s = after(delay, s, "vcast_cn_update_0(6)");
  CHECK(get(delay, s, "held") == 1);
  CHECK(has(steps(delay, s), "vcast'_cn_update_0(6)"));
  s = after(delay, s, "tick"); // may wait up to e = 1
  CHECK(get(delay, s, "age") == 1);
  CHECK_FALSE(has(steps(delay, s), "tick"));
  s = after(delay, s, "vcast'_cn_update_0(6)");
  CHECK(get(delay, s, "held") == 0);
  CHECK(has(steps(delay, s), "tick"));

  c.e = 0;
  const auto urgent = vlayer_mc::vbdelay(c, 0);
  CHECK_FALSE(has(steps(urgent, after(urgent, start(urgent), "vcast_cn_update_0(6)")), "tick"));
}
