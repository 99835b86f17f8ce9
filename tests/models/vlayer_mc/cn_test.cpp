// CN(δ)_p (seed 000 §5.3, reconstructed: README D1–D5) on hand-made states.
#include <catch2/catch.hpp>

#include "models/vlayer_mc/cn.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;

TEST_CASE("vlayer CN: a round of one client", "[vlayer]") {
  const vlayer_mc::VlConfig c; // δ 6, vmax 4, 1×2 with b 2: points y·5 + x
  const auto cn = vlayer_mc::cn(c, 0);
  Words s = start(cn);
  CHECK_FALSE(get(cn, s, "clock"));
  CHECK_FALSE(get(cn, s, "x"));
  // No information: it must stop (velocity 0) before time passes (§5.3 (iii)).
  auto all = steps(cn, s);
  CHECK_FALSE(has(all, "tick"));
  CHECK(only(all, "velocity_0").size() == 1);
  s = after(cn, s, "velocity_0(-1)");
  CHECK(has(steps(cn, s), "tick"));

  s = after(cn, s, "GPSupdate_0(6,5)"); // at (1, 1), one quantum before a round starts
  CHECK(get(cn, s, "x") == 6);
  CHECK(get(cn, s, "clock") == 5);
  s = after(cn, s, "tick");
  all = steps(cn, s);
  CHECK_FALSE(has(all, "tick")); // the cn-update is due (§5.3 (i))
  CHECK(only(all, "vcast_cn_update_0").size() == 1);
  s = after(cn, s, "vcast_cn_update_0(6)");
  CHECK_FALSE(get(cn, s, "target"));
  all = steps(cn, s);
  CHECK(only(all, "vcast_cn_update_0").empty()); // once per round start (D3)
  CHECK(has(all, "tick"));
  s = after(cn, s, "tick");

  s = after(cn, s, "vrcv_target_update_0(1,8)"); // VN_1 sends it to o_1 = (3, 1)
  CHECK(get(cn, s, "target") == 8);
  CHECK_FALSE(has(steps(cn, s), "tick")); // a new velocity at once (§5.3 (ii))
  s = after(cn, s, "velocity_0(8)");
  s = after(cn, s, "tick");
  CHECK(get(cn, s, "x") == 8); // 2 ≤ vmax lattice units: there in one quantum
  CHECK_FALSE(has(steps(cn, s), "tick"));
  s = after(cn, s, "velocity_0(-1)"); // arrived: velocity 0
  CHECK(has(steps(cn, s), "tick"));
}
