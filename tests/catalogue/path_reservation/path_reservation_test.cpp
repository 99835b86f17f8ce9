// The path-reservation model (models/path_reservation/): every scenario explored
// exhaustively, its state count and the verdict of each property pinned; the broken
// variant shows each safety check failing; the findings P1 and P2 of the README replayed.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "tests/catalogue/path_reservation/run_check.hpp"

using checker::Verdict;
using path_reservation_test::run;
using path_reservation_test::run_with;

namespace {

struct Pin {
  const char* scenario;
  std::uint64_t states, edges;
  Verdict progress;
};

// Exact counts of the paper's protocol with the default readings (every property explores
// the same reachable states).
const Pin pins[] = {
    {"crossing", 60, 90, Verdict::holds},           {"head-on", 220, 342, Verdict::violated},
    {"convoy", 1802, 4882, Verdict::holds},         {"cycle", 2475, 7224, Verdict::holds},
    {"late-joiner", 2915, 7929, Verdict::violated}, {"convoy-3x2", 9376, 25201, Verdict::violated},
};

// The same, as the model was before its channels held several messages (issue 16): one
// message of each kind per pair, delivered at any distance, the release and the next
// Discover one step. With those two readings the channels of network.hpp give exactly the
// counts pinned then, which cross-checks the new channels against the old slots.
const Pin earlier_pins[] = {
    {"crossing", 50, 71, Verdict::holds},           {"head-on", 186, 286, Verdict::violated},
    {"convoy", 1749, 4741, Verdict::holds},         {"cycle", 2475, 7224, Verdict::holds},
    {"late-joiner", 2487, 6678, Verdict::violated},
};

} // namespace

TEST_CASE("path-reservation: every scenario is safe, with its exact state count",
          "[path-reservation]") {
  for (const Pin& pin : pins) {
    INFO(pin.scenario);
    for (const char* property : {"mutual-exclusion", "integrity", "no-collision"}) {
      INFO(property);
      const auto r = run(pin.scenario, property);
      CHECK(r.verdict == Verdict::holds);
      CHECK(r.states == pin.states);
      CHECK(r.edges == pin.edges);
    }
    const auto progress = run(pin.scenario, "progress");
    CHECK(progress.verdict == pin.progress);
    CHECK(progress.states == pin.states);
  }
}

TEST_CASE("path-reservation: with the earlier readings, the earlier exact counts",
          "[path-reservation]") {
  const std::vector<std::string> earlier{"delivery=anywhere", "release_step=with-discover"};
  for (const Pin& pin : earlier_pins) {
    INFO(pin.scenario);
    const auto safe = run(pin.scenario, "mutual-exclusion", earlier);
    CHECK(safe.verdict == Verdict::holds);
    CHECK(safe.states == pin.states);
    CHECK(safe.edges == pin.edges);
    CHECK(run(pin.scenario, "progress", earlier).verdict == pin.progress);
  }
  const auto pinwheel = run("pinwheel", "no-collision", earlier);
  CHECK(pinwheel.states == 1149348);
  CHECK(pinwheel.edges == 6088924);
}

TEST_CASE("path-reservation: the four robots of pinwheel (1 150 528 states) stay apart",
          "[path-reservation]") {
  const auto r = run("pinwheel", "no-collision");
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.states == 1150528);
  CHECK(r.edges == 6094424);
}

// [long] (opt-in: ctest -L long): five robots, explored completely (README, "Scenarios and
// verdicts"; several minutes on two threads).
TEST_CASE("path-reservation: five robots of convoy-5x2, every state explored",
          "[path-reservation][long]") {
  const auto safe = run("convoy-5x2", "mutual-exclusion");
  CHECK(safe.verdict == Verdict::holds);
  CHECK(safe.states == 35346501);
  CHECK(safe.edges == 187569533);
  const auto progress = run("convoy-5x2", "progress");
  CHECK(progress.verdict == Verdict::violated);
  CHECK(progress.trace_kind == "deadlock");
}

// Robots in corridors C apart never hear each other, so the state graph of k copies of
// head-on is the product of k copies of head-on's (220 states, 342 edges): 220^k states
// and k * 342 * 220^(k-1) edges, an independent check of the explorer's counts.
TEST_CASE("path-reservation: two head-on pairs out of range multiply", "[path-reservation]") {
  const auto file = std::filesystem::temp_directory_path() / "tioa-two-corridors.txt";
  {
    std::ofstream out(file);
    out << "plane 5 6\nrange 5\n"
        << "robot (0,0) (2,0) (4,0)\nrobot (4,0) (2,0) (0,0)\n"
        << "robot (0,5) (2,5) (4,5)\nrobot (4,5) (2,5) (0,5)\n";
  }
  const auto r = run_with({"scenario_file=" + file.string()}, "mutual-exclusion");
  std::filesystem::remove(file);
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.states == 220u * 220u);
  CHECK(r.edges == 2u * 342u * 220u);
}

// [long]: the same with six robots (scenarios/three-corridors.txt; about a minute).
TEST_CASE("path-reservation: three head-on pairs out of range multiply, six robots",
          "[path-reservation][long]") {
  const auto r = run_with({std::string("scenario_file=") + TIOA_SOURCE_DIR +
                           "/models/path_reservation/scenarios/three-corridors.txt"},
                          "mutual-exclusion");
  CHECK(r.verdict == Verdict::holds);
  CHECK(r.states == 220u * 220u * 220u);
  CHECK(r.edges == 3u * 342u * 220u * 220u);
}

TEST_CASE("path-reservation: releasing before reserving breaks every safety property",
          "[path-reservation]") {
  for (const char* property : {"mutual-exclusion", "integrity", "no-collision"}) {
    INFO(property);
    const auto r = run("crossing", property, {"variant=release-before-reserve"});
    REQUIRE(r.verdict == Verdict::violated);
    REQUIRE(r.trace);
    CHECK(r.trace_kind == "invariant");
  }
  CHECK(run("crossing", "integrity", {"variant=release-before-reserve"}).trace->steps.size() == 10);
}

TEST_CASE("path-reservation: on the cycle of three cells every robot raises risk-cycle",
          "[path-reservation]") {
  for (const char* sort : {"distance", "id"}) {
    INFO(sort);
    const auto r = run("cycle", "progress", {std::string("sort=") + sort});
    REQUIRE(r.verdict == Verdict::holds);
    REQUIRE(r.trace); // the worst-case witness: it ends with all three halted
    const auto& last = r.trace->steps.back();
    const auto& definition = catalogue::builtin_models().find("path-reservation");
    const auto instance = definition.build(
        catalogue::resolve_params(definition, {"scenario=cycle", std::string("sort=") + sort}));
    for (int robot = 1; robot <= 3; ++robot) {
      const auto* info = instance.system.layout().find("exception[" + std::to_string(robot) + "]");
      REQUIRE(info);
      CHECK(info->render_code(tioa::State(last.state.data(), 0).code(info->slot())) ==
            "risk-cycle");
    }
  }
}

TEST_CASE("path-reservation: finding P1, head-on robots wait for each other forever",
          "[path-reservation]") {
  const auto r = run("head-on", "progress");
  REQUIRE(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "deadlock");
  CHECK(r.trace->length() == 15);
  // The AfterMe R2 sent is dropped by R1, which has already taken R2's request as msg_2.
  CHECK(r.trace->steps.back().action == "receive_AfterMe(2,1)");
}

namespace {

// The value of `variable`, as reports print it, in the last state of r's trace.
std::string last_value(const checker::PropertyResult& r, const std::string& variable,
                       const std::vector<std::string>& settings) {
  const auto& definition = catalogue::builtin_models().find("path-reservation");
  std::vector<std::string> all = settings;
  all.push_back("scenario=convoy-3x2");
  const auto instance = definition.build(catalogue::resolve_params(definition, all));
  const auto* info = instance.system.layout().find(variable);
  REQUIRE(info);
  const auto& last = r.trace->steps.back();
  return info->render_code(tioa::State(last.state.data(), 0).code(info->slot()));
}

} // namespace

TEST_CASE("path-reservation: finding P6, a convoy waits for a release that never comes",
          "[path-reservation]") {
  // The most charitable reading: round tags, the literal msg_j rule, FIFO channels,
  // messages delivered at any distance. R3 learns from R2's AfterMe list that R2 is
  // after R1, so (Algorithm 2 line 7) R3 is after R1 too; but R1, which never had R3 in
  // its group, has released and finished.
  const std::vector<std::string> readings{"variant=round-tags", "msg_rule=any-zone",
                                          "channels=fifo", "delivery=anywhere"};
  const auto r = run("convoy-3x2", "progress-unless-detected", readings);
  REQUIRE(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "deadlock");
  CHECK(last_value(r, "phase[1]", readings) == "done");
  CHECK(last_value(r, "phase[2]", readings) == "done");
  CHECK(last_value(r, "phase[3]", readings) == "waiting");
  CHECK(last_value(r, "WLAfter_to[3]", readings) == "{R1, R2}");
  CHECK(last_value(r, "released[3]", readings) == "{R2}");
}

TEST_CASE("path-reservation: finding P7, an Overlap list stranded out of range",
          "[path-reservation]") {
  // The default readings (delivery within C): R1 reserves, goes and finishes before R2
  // has read R1's Overlap list; R1 ends 6 cells from R2 (C = 5), so the list never passes.
  const auto r = run("convoy-3x2", "progress");
  REQUIRE(r.verdict == Verdict::violated);
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "deadlock");
  CHECK(last_value(r, "phase[1]", {}) == "done");
  CHECK(last_value(r, "phase[2]", {}) == "exchanging");
  CHECK(last_value(r, "net[1][2][0].kind", {}) == "Overlap");
  // Delivered at any distance, the list passes and this deadlock is gone (P1 remains:
  // the trace is another one).
  const auto anywhere = run("convoy-3x2", "progress", {"delivery=anywhere"});
  REQUIRE(anywhere.verdict == Verdict::violated);
  CHECK(anywhere.trace->steps.back().action == "receive_AfterMe(2,3)");
}

TEST_CASE("path-reservation: the scenarios are checked, bad ones refused in one line",
          "[path-reservation]") {
  for (const auto& s : path_reservation::scenarios()) {
    INFO(s.name);
    CHECK_FALSE(path_reservation::check_scenario(s));
  }
  path_reservation::Scenario far = path_reservation::find_scenario("crossing");
  far.range = 4; // a chunk of three cells leaves Cir(start, C/2 = 2)
  const auto why = path_reservation::check_scenario(far);
  REQUIRE(why);
  CHECK(why->find("Definition 4") != std::string::npos);
  path_reservation::Scenario bent = far;
  bent.range = 6;
  bent.paths[0] = {{0, 2}, {2, 3}};
  REQUIRE(path_reservation::check_scenario(bent));
  CHECK(path_reservation::check_scenario(bent)->find("not horizontal, vertical or diagonal") !=
        std::string::npos);
  CHECK_THROWS_AS(path_reservation::find_scenario("nowhere"), std::invalid_argument);
}

TEST_CASE("path-reservation: zones, disks and distances on the plane", "[path-reservation]") {
  const path_reservation::Plane plane(4, 4);
  const auto zone = plane.zone({0, 2}, {3, 2});
  CHECK(zone.pre == plane.bit({0, 2}));
  CHECK(zone.post == plane.bit({3, 2}));
  CHECK(__builtin_popcountll(zone.motion) == 4);
  // Cir((0,0), 1.5) holds the cells at distance <= 1.5: (0,0), (1,0), (0,1), (1,1).
  CHECK(__builtin_popcountll(plane.disk({0, 0}, 9)) == 4);
  CHECK(plane.squared_distance({0, 0}, plane.bit({2, 2}) | plane.bit({3, 0})) == 8);
  CHECK_THROWS_AS(path_reservation::Plane(9, 8), std::invalid_argument);
}
