// What U(VLNodes) may leave in a client's buffer (D31: junk slots of VBDelay and VBcast) and
// the d_r rule (D32: VW keeps a VSA with a settled client alive), on hand-made states.
#include <catch2/catch.hpp>

#include "checker/checks.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/vbcast.hpp"
#include "models/vlayer_mc/vbdelay.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "models/vlayer_mc/vw.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"
#include "tioa/operators.hpp"

using namespace vl_test;

TEST_CASE("vlayer junk (D31): VBDelay hands U's messages to VBcast within e", "[vlayer]") {
  vlayer_mc::VlConfig c; // 1×2, e = 0
  c.robots = 2;
  c.junk = 2;
  const auto delay = vlayer_mc::vbdelay(c, 0);
  Words d = start(delay);
  CHECK(only(steps(delay, d), "vcast'_junk").empty()); // the instance's start: no junk
  CHECK(has(steps(delay, d), "tick"));
  set(delay, d, "junk_kind[1]", 3); // ⟨target-update, 1, 8⟩
  set(delay, d, "junk_id[1]", 1);
  set(delay, d, "junk_value[1]", 8);
  const auto all = steps(delay, d);
  CHECK(only(all, "vcast'_junk").size() == 1);
  CHECK(has(all, "vcast'_junk_0(1,3,1,8)"));
  CHECK_FALSE(has(all, "tick")); // e = 0: it leaves at once
  d = after(delay, d, "vcast'_junk_0(1,3,1,8)");
  CHECK(get(delay, d, "junk_kind[1]") == 0);
  CHECK(has(steps(delay, d), "tick"));

  c.e = 2; // with e = 2 it may wait two quanta
  const auto slow = vlayer_mc::vbdelay(c, 0);
  Words w = start(slow);
  set(slow, w, "junk_kind[0]", 1);
  w = after(slow, after(slow, w, "tick"), "tick");
  CHECK_FALSE(has(steps(slow, w), "tick"));
  CHECK(has(steps(slow, w), "vcast'_junk_0(0,1,0,0)"));
}

TEST_CASE("vlayer junk (D31): VBcast delivers U's messages to the receivers they affect",
          "[vlayer]") {
  vlayer_mc::VlConfig c; // 1×2: point 6 = (1, 1) in region 0, point 8 = (3, 1) in region 1
  c.robots = 2;
  c.junk = 2;
  const auto vb = vlayer_mc::vbcast(c);
  Words s = start(vb);
  // Before client 0's first GPSupdate VBcast does not know where it is: nobody (D10).
  CHECK(get(vb, after(vb, s, "vcast'_junk_0(1,3,1,8)"), "junk_to[1]") == 0);
  s = after(vb, s, "GPSupdate_0(6,0)");
  s = after(vb, s, "GPSupdate_1(8,0)");
  // Client 0 (region 0) sends a target for robot 1 (region 1, a neighbour): CN_1 gets it,
  // with the sender's region as the VN's id. A delivery's choice names the copy: 0 the
  // sender's own slot, 1 + i junk slot i (client 0's slots 0 and 1, client 1's 2 and 3).
  s = after(vb, s, "vcast'_junk_0(1,3,1,8)");
  CHECK(get(vb, s, "junk_to[1]") == 1);
  CHECK(get(vb, s, "junk_from[1]") == 0);
  CHECK(only(steps(vb, s), "vrcv_target_update_1").size() == 1);
  CHECK(has(steps(vb, s), "vrcv_target_update_1(0,8) [choice 2]"));
  // A cn-update about robot 1 at point 6 goes to VN_0; robot 1's own cn-update of the same
  // point is a second copy: one choice per copy.
  s = after(vb, s, "vcast'_junk_0(0,1,1,6)");
  CHECK(has(steps(vb, s), "vrcv_cn_update_0(1,6) [choice 1]"));
  s = after(vb, s, "vcast'_cn_update_1(6)");
  const auto copies = only(steps(vb, s), "vrcv_cn_update_0(1,6)");
  REQUIRE(copies.size() == 2);
  CHECK(get(vb, copies[0].state, "cn_pending[1]") == 0); // the sender's own slot first
  CHECK(get(vb, copies[0].state, "junk_to[0]") == 1);
  CHECK(get(vb, copies[1].state, "cn_pending[1]") == 1);
  CHECK(get(vb, copies[1].state, "junk_kind[0]") == 0); // delivered: the slot is emptied
  // A vn-update about region 0 from client 1 (region 1): VN_1 has region 0 as a neighbour,
  // VN_0 does not (D11). A count above N reaches nobody.
  s = after(vb, s, "vcast'_junk_1(0,2,0,2)");
  CHECK(get(vb, s, "junk_to[2]") == 2);
  CHECK(has(steps(vb, s), "vrcv_vn_update_1(0,2) [choice 3]"));
  CHECK(get(vb, after(vb, s, "vcast'_junk_1(1,2,0,5)"), "junk_to[3]") == 0);
  // Within d = 1: at age 1 time cannot pass while a receiver waits.
  s = after(vb, s, "tick");
  CHECK(get(vb, s, "junk_age[2]") == 1);
  CHECK_FALSE(has(steps(vb, s), "tick"));
}

TEST_CASE("vlayer junk (D31): ResetMC needs the junk slots empty", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.junk = 1;
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  Words s(layer.words() + 1, 0);
  vlayer_mc::placed_start(layer, {c.lattice().point(1, 1)}).enumerate(s.data(), 0, [] {});
  const auto clauses = [&](Words w) {
    return vlayer_mc::reset_mc_clauses(c, layer)(tioa::State(w.data(), 0));
  };
  CHECK(clauses(s).empty());
  Words held = s;
  set(layer, held, "CN_0.delay.junk_kind[0]", 2);
  CHECK(clauses(held) == std::vector<std::string>{"(2) CN_0"});
  Words pending = s;
  set(layer, pending, "VBcast.junk_kind[0]", 2);
  set(layer, pending, "VBcast.junk_to[0]", 1);
  CHECK(clauses(pending) == std::vector<std::string>{"(4)"});
}

namespace {

// VLayer[MC] on 1×1 with one robot at point 4 (region 0), VN_0 failed at the start.
tioa::Automaton failed_vsa_layer(bool dr_rule, bool vsa_faults) {
  vlayer_mc::VlConfig c;
  c.cols = 1;
  c.dr_rule = dr_rule;
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = vsa_faults});
  Words s(layer.words() + 1, 0);
  vlayer_mc::placed_start(layer, {4}).enumerate(s.data(), 0, [] {});
  s.resize(layer.words());
  set(layer, s, "VN_0.failed", 1);
  return tioa::Start(layer, tioa::StartSet::listed(layer.layout().bits(), layer.words(), s,
                                                   "VN_0 failed, the robot at point 4"));
}

// The property of D32 as an invariant: while VW has made its restart for a settled region,
// the VSA is alive.
checker::PropertyResult kept_alive(const tioa::Automaton& layer) {
  const auto kept = tioa::find_variable<bool>(layer, "VW.kept[0]");
  const auto failed = tioa::find_variable<bool>(layer, "VN_0.failed");
  return checker::check_invariant(layer,
                                  [=](const tioa::State& s) { return !s[kept] || !s[failed]; }, {});
}

} // namespace

TEST_CASE("vlayer d_r rule (D32): VW restarts a failed VSA once a client settles", "[vlayer]") {
  // Without the rule, nothing restarts VN_0: it stays failed in every reachable state.
  const auto without = failed_vsa_layer(false, false);
  const auto failed = tioa::find_variable<bool>(without, "VN_0.failed");
  CHECK(checker::check_invariant(without, [=](const tioa::State& s) { return s[failed]; }, {})
            .verdict == checker::Verdict::holds);

  // With it, the robot's first GPSupdate puts it in region 0; d_r = 1 later VW restarts VN_0.
  const auto with = failed_vsa_layer(true, false);
  const auto failed_with = tioa::find_variable<bool>(with, "VN_0.failed");
  const auto r =
      checker::check_invariant(with, [=](const tioa::State& s) { return s[failed_with]; }, {});
  CHECK(r.verdict == checker::Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace->steps.back().action == "restart_VN_0");
  CHECK(r.trace->steps.back().time == 1u);
  CHECK(kept_alive(with).verdict == checker::Verdict::holds);

  // With VSA faults VW fails VN_0 whenever the rule lets it: before the robot settles, never
  // after.
  const auto faulty = failed_vsa_layer(true, true);
  CHECK(kept_alive(faulty).verdict == checker::Verdict::holds);
  const auto kept = tioa::find_variable<bool>(faulty, "VW.kept[0]");
  const auto failed_faulty = tioa::find_variable<bool>(faulty, "VN_0.failed");
  const auto restarted = checker::check_invariant(
      faulty, [=](const tioa::State& s) { return s[kept] || s[failed_faulty]; }, {});
  REQUIRE(restarted.trace); // a restart before the robot settles, which VW may fail again
  CHECK(restarted.verdict == checker::Verdict::violated);
}
