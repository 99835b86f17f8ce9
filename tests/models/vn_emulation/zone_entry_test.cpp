// E5 (models/vn_emulation/README.md): two zones at the paper's radius (R_p² = 20), one fail,
// one move. PN_1 enters B_0 in the instant of a reset: it has dropped a TOBcast message of
// B_0 that reached it while it still stood in B_1 (D13: TOBcast_{i,h} only processes
// messages tagged for zone B_h, 002:348), then receives the reset of the same instant and,
// joining, takes it (a reset starts the VN whatever the status, 002:352, D5). At the
// delivery instant PN_0 and PN_1 are both active replicas of VN_0, and only PN_0 executes
// the message. `check vn-emulation -p zones=2,fails=1,moves=1 --prop replica-consistency`
// finds this 43-step trace as its shortest counterexample (72 million states, 3 minutes,
// 16 GB); the test follows it step by step.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/models/vn_emulation/schedule.hpp"

namespace {

vn_emulation::EmuConfig e5_instance(bool reset_joined, bool tobcast_zone_at_delivery = false) {
  vn_emulation::EmuConfig c;
  c.zones = 2;
  c.fails = 1;
  c.moves = 1;
  c.reset_joined = reset_joined;
  c.tobcast_zone_at_delivery = tobcast_zone_at_delivery;
  return c;
}

// PN_0 and PN_1 both active replicas of VN_0.
vn_emulation_schedule::Predicate both_active(const vn_emulation::Emulation& e) {
  return [&e](const tioa::State& s) {
    const auto& p = e.slots->pns;
    return s[p[0].status] == vn_emulation::Status::active &&
           s[p[1].status] == vn_emulation::Status::active && s[p[1].zone] == 0;
  };
}

const std::vector<std::string> e5_schedule = {
    "fail_0",
    "recover_0",
    "zone-update_0",
    "join_0", // VN_0's only replica rejoins at 0
    "TOBcast_0",
    "lb-rcv_0(0,0)",
    "lb-rcv_1(0,0)",
    "tick",
    "tick",
    "TOBcast-rcv_0", // PN_0 listens from 2; nobody acks its join
    "tick",
    "tick",
    "tick",
    "tick",
    "cn-send_0",     // CN_0's message at 6
    "lb-rcv_1(0,0)", // PN_1, in B_1, ignores it
    "tick",
    "restart_0",     // at 7 = 3d_p + 4eps after its join, PN_0 resets VN_0: ⟨7, 0, 0⟩
    "TOBcast_0",     //
    "lb-rcv_0(0,0)", // PN_0 receives CN_0's message and suggests receive(m0) ...
    "TOBcast_0",     // ... ⟨7, 0, 1⟩
    "lb-rcv_0(0,0)", // PN_0 holds the reset
    "lb-rcv_0(0,1)", // and the suggestion
    "lb-rcv_1(0,1)", // PN_1, still in B_1, drops the suggestion (tagged B_0)
    "move_1(0)",     // PN_1 steps west into B_0
    "zone-update_1",
    "join_1",
    "TOBcast_1",
    "lb-rcv_0(1,0)",
    "lb-rcv_1(0,0)", // PN_1 holds the reset (it stands in B_0 now)
    "lb-rcv_1(1,0)", // and its own join-req, after the reset in TOBcast's order
    "tick",
    "tick",
    "TOBcast-rcv_0",     // at 9: PN_0 takes the reset (VN_0 starts) ...
    "TOBcast-rcv_0",     // ... and the suggestion
    "simulate-action_0", // count 1
    "init-action_0",
    "TOBcast_0",
    "TOBcast-rcv_0",
    "TOBcast-rcv_1", // PN_1, joining, takes the reset: active with VN_0's start state
    "TOBcast-rcv_1",
    "ack-join_1",
    "TOBcast_1"};

// PN_0 at point 0 (B_0), PN_1 at point 4 (B_1).
vn_emulation_schedule::Predicate e5_placement(const vn_emulation::Emulation& e) {
  return [&e](const tioa::State& s) {
    return s[*e.slots->pns[0].point] == 0 && s[*e.slots->pns[1].point] == 4;
  };
}

} // namespace

TEST_CASE("vn-emulation E5: a PN that enters a zone in the instant of a reset becomes a replica "
          "without a message of that instant",
          "[vn-emulation]") {
  const vn_emulation::Emulation e = vn_emulation::emulation(e5_instance(false));
  const vn_emulation_schedule::Walk w =
      vn_emulation_schedule::walk(e, e5_schedule, 10, e5_placement(e));
  REQUIRE(w.failure);
  CHECK(w.trace.length() == e5_schedule.size());
  CHECK(*w.failure == "the active replicas PN_0 and PN_1 hold different VN states where time "
                      "passes: (count 1, last CN_0, out [<1, CN_0>], sseq 0) and (count 0, last "
                      "⊥, out [], sseq 0)");
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(e.automaton), w.trace, &why));
  INFO(why);
}

TEST_CASE("vn-emulation E5 repaired: a joiner that takes no reset before its own join-req is "
          "acked with the VN's state",
          "[vn-emulation]") {
  // The schedule up to PN_1's delivery of the reset (which it now ignores), then the first
  // step offered: PN_0 acks PN_1's join-req, and the two replicas agree.
  const vn_emulation::Emulation e = vn_emulation::emulation(e5_instance(true));
  const std::vector<std::string> prefix(e5_schedule.begin(), e5_schedule.end() - 3);
  const vn_emulation_schedule::Walk w =
      vn_emulation_schedule::walk(e, prefix, 20, e5_placement(e), both_active(e));
  CHECK_FALSE(w.failure);
  CHECK(w.watched > 0);
}

TEST_CASE("vn-emulation E5 rests on D13: a TOBcast that keeps other zones' packets until their "
          "delivery gives the joiner the message",
          "[vn-emulation]") {
  // tobcast_zone=delivery: PN_1 keeps the suggestion it received in B_1; at 9 it delivers
  // the reset and then the suggestion, as PN_0 does, and the replicas agree.
  const vn_emulation::Emulation e = vn_emulation::emulation(e5_instance(false, true));
  const auto entered = std::find(e5_schedule.begin(), e5_schedule.end(), "lb-rcv_1(1,0)");
  REQUIRE(entered != e5_schedule.end());
  std::vector<std::string> prefix(e5_schedule.begin(), entered + 1);
  // PN_1, in B_1, now also holds PN_0's join-req, and drops it at its delivery at 2.
  const auto delivered = std::find(prefix.begin(), prefix.end(), "TOBcast-rcv_0");
  prefix.insert(delivered + 1, "TOBcast-rcv_1");
  const vn_emulation_schedule::Walk w =
      vn_emulation_schedule::walk(e, prefix, 20, e5_placement(e), both_active(e));
  CHECK_FALSE(w.failure);
  CHECK(w.watched > 0);
}
