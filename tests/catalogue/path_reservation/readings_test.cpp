// The readings of seed 004 that the README marks as decisions, each with its alternative:
// Definition 4's disk (finding P3, scenario range-edge), which request is msg_j, and what
// a robot does with a request before it knows G_i. Do findings P1 and P2 survive?
#include <catch2/catch.hpp>

#include "models/path_reservation/geometry.hpp"
#include "tests/catalogue/path_reservation/run_check.hpp"
#include "tioa/errors.hpp"

using checker::Verdict;
using path_reservation_test::run;

TEST_CASE("path-reservation: finding P3, zones that meet at distance exactly C collide",
          "[path-reservation][readings]") {
  // The two robots are C = 4 apart and never hear each other; each zone lies in its
  // closed disk Cir(start, 2) and both end on the middle cell.
  const auto exclusion = run("range-edge", "mutual-exclusion");
  REQUIRE(exclusion.verdict == Verdict::violated);
  REQUIRE(exclusion.trace);
  CHECK(exclusion.trace->steps.back().action == "reserve(2)");
  const auto collision = run("range-edge", "no-collision");
  REQUIRE(collision.verdict == Verdict::violated);
  CHECK(collision.trace->steps.back().action == "move(2)");
  CHECK(run("range-edge", "integrity").verdict == Verdict::holds);
  CHECK(run("range-edge", "progress").verdict == Verdict::holds);
  // As an open disk, Definition 4 refuses the scenario: no cell is then within C/2 of
  // both robots unless they are closer than C, and so hear each other.
  try {
    run("range-edge", "no-collision", {"disk=open"});
    FAIL("range-edge was accepted with an open disk");
  } catch (const tioa::ModelError& e) {
    CHECK(std::string(e.what()).find("leaves the open disk") != std::string::npos);
  }
}

TEST_CASE("path-reservation: an open disk leaves out the cells on its edge",
          "[path-reservation][readings]") {
  const path_reservation::Plane plane(5, 1);
  using path_reservation::DiskEdge;
  CHECK(plane.disk({0, 0}, 16, DiskEdge::closed) == 0b00111); // distance <= 2
  CHECK(plane.disk({0, 0}, 16, DiskEdge::open) == 0b00011);   // distance < 2
  // Scenarios whose zones stay inside the open disk keep their verdicts.
  CHECK(run("head-on", "progress", {"disk=open"}).verdict == Verdict::violated);
  CHECK(run("convoy", "no-collision", {"disk=open"}).verdict == Verdict::holds);
}

TEST_CASE("path-reservation: P1 and P2 survive taking any request of R_j as msg_j",
          "[path-reservation][readings]") {
  const std::vector<std::string> any{"msg_rule=any-zone"};
  for (const char* scenario : {"crossing", "head-on", "convoy", "cycle", "late-joiner"})
    for (const char* property : {"mutual-exclusion", "integrity", "no-collision"}) {
      INFO(scenario << " " << property);
      CHECK(run(scenario, property, any).verdict == Verdict::holds);
    }
  for (const char* scenario : {"crossing", "convoy", "cycle"}) {
    INFO(scenario);
    CHECK(run(scenario, "progress", any).verdict == Verdict::holds);
  }
  // head-on: R1 answered R2's first request from its Reply thread, and R2 now takes R1's
  // request for its second chunk as msg_1 and drops R1's late AfterMe. R1 waits for a
  // msg_2 that R2 has already sent (README, P1).
  const auto head_on = run("head-on", "progress", any);
  REQUIRE(head_on.verdict == Verdict::violated);
  REQUIRE(head_on.trace);
  CHECK(head_on.trace->length() == 16);
  CHECK(head_on.states == 200);
  CHECK(run("late-joiner", "progress", any).verdict == Verdict::violated);
}

TEST_CASE("path-reservation: answering requests before G_i is known deadlocks even crossing",
          "[path-reservation][readings]") {
  const auto r = run("crossing", "progress", {"early_requests=answer"});
  REQUIRE(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "deadlock");
  CHECK(r.trace->steps.size() == 10);
  // The AfterMe that R2 sent while still discovering arrives after R1 took R2's own
  // request as msg_2, and is dropped.
  CHECK(r.trace->steps.back().action == "receive_AfterMe(2,1)");
  CHECK(run("crossing", "mutual-exclusion", {"early_requests=answer"}).verdict == Verdict::holds);
}
