// How often each branch of seed 002 Fig. 7 fired (issue 15, "sizes where the algorithm
// acts"): every vlayer-mc property reports it, and the instances named in the README make
// each branch act. Counts are distinct computations (models/vlayer_mc/branch_tally.hpp),
// so threads and repeated runs give the same figures.
#include <catch2/catch.hpp>

#include "catalogue/registry.hpp"
#include "catalogue/vlayer_mc.hpp"
#include "checker/property.hpp"
#include "tests/catalogue/vlayer_mc/vl_results.hpp"

using vl_test::figure;

namespace {

const char* const computations = "Fig. 7 computations (distinct)";
const char* const on_curve = "Fig. 7 lines 7-12 on the curve, reassigning";
const char* const no_curve_neighbour = "Fig. 7 lines 13-18 no curve neighbour, reassigning";
const char* const boundary = "Fig. 7 lines 19-22 boundary, reassigning";
const char* const to_centre = "Fig. 7 lines 30-31 robots to a neighbour's centre";

// no-timelock on `settings`, reduced, with at most `max_states` states (0: all).
checker::PropertyResult no_timelock(const std::vector<std::string>& settings,
                                    std::uint64_t max_states, unsigned threads = 1) {
  const catalogue::ModelDefinition def = catalogue::vlayer_mc_definition();
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, settings));
  checker::ExploreOptions o;
  o.por = true;
  o.limits.max_states = max_states;
  o.threads = threads;
  return checker::run_property(m.system, m.properties.at(0), o);
}

std::uint64_t count(const checker::PropertyResult& r, const char* name) {
  const std::string text = figure(r, name);
  REQUIRE_FALSE(text.empty());
  return std::stoull(text);
}

} // namespace

TEST_CASE("vlayer-mc Fig. 7: the default instance never reassigns a robot", "[vlayer]") {
  const auto r = no_timelock({}, 0);
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(count(r, computations) > 0);
  for (const char* branch : {on_curve, no_curve_neighbour, boundary, to_centre})
    CHECK(count(r, branch) == 0);
}

TEST_CASE("vlayer-mc Fig. 7: two robots off the curve, the boundary sends one (lines 19-22)",
          "[vlayer]") {
  const auto r = no_timelock({"rows=2", "cols=1", "robots=2"}, 0);
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(count(r, boundary) == 1);  // ⌊(2 − k)/|In|⌋ = 1, from the start placement
  CHECK(count(r, to_centre) == 1); // line 31: to o_0
  CHECK(count(r, on_curve) == 0);
  // Distinct computations: the same with two threads, and on a second run of the instance.
  const auto twice = no_timelock({"rows=2", "cols=1", "robots=2"}, 0, 2);
  CHECK(twice.figures == r.figures);
}

TEST_CASE("vlayer-mc Fig. 7: five robots in one region of the curve (lines 7-12, 31)", "[vlayer]") {
  // y(0) = 5, y(1) = 0: ⌊ρ2·5/4⌋ = 1 robot to o_1; the first compute step is early.
  const auto r = no_timelock({"robots=5", "place=corner"}, 20'000);
  CHECK(r.verdict == checker::Verdict::incomplete);
  CHECK(count(r, on_curve) >= 1);
  CHECK(count(r, to_centre) >= 1);
}

TEST_CASE("vlayer-mc Fig. 7: five robots two rows off the curve (lines 13-18, 31)", "[vlayer]") {
  // Region 2 (row 2) has no neighbour on the curve: In = ∅, lower = {1}, one robot sent.
  const auto r = no_timelock({"rows=3", "cols=1", "robots=5", "place=corner"}, 20'000);
  CHECK(r.verdict == checker::Verdict::incomplete);
  CHECK(count(r, no_curve_neighbour) >= 1);
  CHECK(count(r, to_centre) >= 1);
}

TEST_CASE("vlayer-mc: place=row needs a lattice as wide as the robots", "[vlayer]") {
  const catalogue::ModelDefinition def = catalogue::vlayer_mc_definition();
  CHECK_THROWS_AS(catalogue::resolve_params(def, {"robots=6"}), catalogue::UsageError);
  CHECK_NOTHROW(catalogue::resolve_params(def, {"robots=5"})); // 1×2, b 2: 5 points wide
  CHECK_NOTHROW(catalogue::resolve_params(def, {"robots=6", "place=corner"}));
  CHECK_THROWS_AS(catalogue::resolve_params(def, {"robots=7", "place=corner"}),
                  catalogue::UsageError);
}
