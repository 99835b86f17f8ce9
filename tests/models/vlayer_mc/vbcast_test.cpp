// VBcast (seed 000 §4.1) on hand-made states: reg(p), the receivers (D11), delivery within d.
#include <catch2/catch.hpp>

#include "models/vlayer_mc/vbcast.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;

TEST_CASE("vlayer VBcast: a cn-update reaches the VN of its location within d", "[vlayer]") {
  const vlayer_mc::VlConfig c; // 1×2, d 1
  const auto vb = vlayer_mc::vbcast(c);
  Words s = start(vb);
  CHECK_FALSE(get(vb, s, "reg[0]"));
  // Before any GPSupdate VBcast does not know where p is: nobody receives (D10).
  CHECK(get(vb, after(vb, s, "vcast'_cn_update_0(8)"), "cn_pending[0]") == 0);
  s = after(vb, s, "GPSupdate_0(6,0)");
  CHECK(get(vb, s, "reg[0]") == 0);
  s = after(vb, s, "vcast'_cn_update_0(8)"); // (3, 1), in region 1, a neighbour of 0
  auto all = steps(vb, s);
  CHECK(has(all, "vrcv_cn_update_1(0,8)"));
  CHECK(only(all, "vrcv_cn_update_0").empty());
  CHECK(has(all, "tick"));
  s = after(vb, s, "tick");
  CHECK(get(vb, s, "cn_age[0]") == 1);
  CHECK_FALSE(has(steps(vb, s), "tick")); // d reached: urgent
  s = after(vb, s, "vrcv_cn_update_1(0,8)");
  CHECK(get(vb, s, "cn_pending[0]") == 0);
  CHECK(get(vb, s, "cn_age[0]") == 0);
  CHECK(has(steps(vb, s), "tick"));
}

TEST_CASE("vlayer VBcast: only nbrs+ of the sender's region receive", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.rows = 2;
  c.cols = 2;
  c.robots = 2;
  const auto vb = vlayer_mc::vbcast(c); // 4-neighbourhood: 0 and 3 are not neighbours
  Words s = start(vb);
  s = after(vb, s, "GPSupdate_0(0,0)");  // robot 0 in region 0
  s = after(vb, s, "GPSupdate_1(24,0)"); // robot 1 at (4, 4), region 3
  s = after(vb, s, "vcast'_cn_update_0(24)");
  CHECK(get(vb, s, "cn_pending[0]") == 0);
  s = after(vb, s, "vcast_vn_update_0(2)");
  CHECK(get(vb, s, "vn_mask[0]") == 3); // nbrs(0) = {1, 2}
  auto all = steps(vb, s);
  CHECK(has(all, "vrcv_vn_update_1(0,2)"));
  CHECK(has(all, "vrcv_vn_update_2(0,2)"));
  CHECK(only(all, "vrcv_vn_update_3").empty());
  s = after(vb, s, "vrcv_vn_update_2(0,2)");
  CHECK(get(vb, s, "vn_mask[0]") == 1);
  // A target-update of VN_0 reaches robot 0 (in region 0), not robot 1 (region 3).
  s = after(vb, s, "vcast_target_update_0(0,6)");
  s = after(vb, s, "vcast_target_update_0(1,6)");
  all = steps(vb, s);
  CHECK(has(all, "vrcv_target_update_0(0,6)"));
  CHECK(only(all, "vrcv_target_update_1").empty());
}
