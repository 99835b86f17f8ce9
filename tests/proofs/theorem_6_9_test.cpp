// Theorem 6.9 / conference Theorem 1 (proofs/theorem_6_9.hpp): part (1) at count level, and
// both parts with positions under the two membership readings, on a small family; the
// finding under the faithful reading pinned with its smallest counterexample.
#include <catch2/catch.hpp>

#include "proofs/theorem_6_9.hpp"

using namespace proofs;

namespace {

Family tiny_counts() {
  Family f;
  f.sides = {{2, 2}};
  f.ks = {1};
  f.rho2s = {{1, 2}};
  return f;
}

PositionalFamily tiny_positions() {
  PositionalFamily f;
  f.sides = {2};
  f.neighbourhoods = {mc::Neighbourhood::four};
  f.max_count = 2;
  f.ks = {1};
  f.rho1s = {{1, 2}};
  f.rho2s = {{1, 2}};
  return f;
}

} // namespace

TEST_CASE("theorem 6.9: the curves of the positional family are exact", "[proofs][theorem-6.9]") {
  for (int m = 1; m <= 4; ++m)
    for (const NamedCurve& curve : positional_curves(m)) {
      INFO("m = " << m << ", curve " << curve.name);
      CHECK_NOTHROW(mc::ExactCurve(curve.curve, mc::GridTiling(m, mc::Neighbourhood::four),
                                   mc::Rational(1, 4)));
    }
  CHECK_THROWS_AS(positional_curves(0), std::invalid_argument);
}

TEST_CASE("theorem 6.9: holds with membership by assignment, fails with membership by position",
          "[proofs][theorem-6.9]") {
  const TheoremCheck check = check_theorem_6_9(tiny_counts(), tiny_positions());
  CHECK(check.result.name == "theorem-6.9");
  CHECK(check.counts.result.verdict == checker::Verdict::holds);
  // 6 curves × 2 readings × 3^4 configurations.
  CHECK(check.runs == 6 * 2 * 81);
  for (const char* id : {"6.9(1) fixed [assigned]", "6.9(1) proportional [assigned]",
                         "6.9(2) on curve [assigned]", "6.9(2) spacing [assigned]"}) {
    INFO(id);
    CHECK(check.claim(id).violations == 0);
    CHECK(check.claim(id).undecided == 0);
    CHECK(check.claim(id).premise > 0);
  }
  CHECK(check.claim("6.9(1) fixed [assigned]").premise == 6 * 81);

  // The finding (models/mc/README.md, "Positions and calctarget"): calctarget sends a robot
  // to an end of Γ_h owned by the next region, and assign sends it back, for ever.
  const PositionalTally& fixed = check.claim("6.9(1) fixed [position]");
  CHECK(fixed.violations > 0);
  REQUIRE(fixed.smallest);
  CHECK(fixed.smallest->robots == 2);
  CHECK(fixed.smallest->setting.find("curve stub") != std::string::npos);
  CHECK(fixed.smallest->why.find("never fixed") != std::string::npos);
  CHECK(check.result.verdict == checker::Verdict::violated);
  CHECK(check.result.message.find("6.9(1) fixed [position]") != std::string::npos);
  // Where the faithful reading does become fixed, the rest of the theorem holds.
  CHECK(check.claim("6.9(2) spacing [position]").violations == 0);
  CHECK(check.claim("6.9(2) on curve [position]").violations == 0);
}

TEST_CASE("theorem 6.9: the counterexample is printed round by round", "[proofs][theorem-6.9]") {
  PositionalFamily only_stub = tiny_positions();
  only_stub.memberships = {mc::Membership::position};
  const TheoremCheck check = check_theorem_6_9(tiny_counts(), only_stub);
  bool printed = false;
  for (const std::string& note : check.result.notes)
    printed = printed || note.find("migrations #0 0->1") != std::string::npos;
  CHECK(printed);
  CHECK_THROWS_AS(check.claim("6.9(1) fixed [assigned]"), std::out_of_range);
}

TEST_CASE("theorem 6.9: a run whose positions never recur is proven never fixed",
          "[proofs][theorem-6.9]") {
  // 6 robots on the westward line (y = 3/2, from x = 2 to x = 0) of a 2×2 grid, as found by
  // the family: the counts cycle (0,1,0,5) → (0,1,1,4) → (0,1,1,4) → … while region 3's robots
  // keep converging, so no state recurs exactly. Region 2's Γ starts at (1,3/2), which region
  // 3 owns: a round can certify only with region 2 empty, and then region 3 sends it a robot.
  const NamedCurve westward = positional_curves(2)[1];
  REQUIRE(westward.name == "westward");
  const mc::PositionSystem system(
      mc::ExactCurve(westward.curve, mc::GridTiling(2, mc::Neighbourhood::four), {1, 4}),
      {1, {1, 2}, {9, 10}}, {mc::Membership::position});
  auto robot = [](mc::RobotId id, mc::Rational x, mc::Rational y) {
    return mc::Robot{id, {std::move(x), std::move(y)}, std::nullopt};
  };
  const std::vector<mc::Robot> start{robot(0, {3, 2}, {1, 2}), robot(1, {9, 8}, {1, 8}),
                                     robot(2, {1, 2}, {3, 2}), robot(3, {1, 8}, {9, 8}),
                                     robot(4, {3, 2}, {3, 2}), robot(5, {9, 8}, {9, 8})};
  const mc::PositionRun run = system.run(start, 40);
  CHECK_FALSE(run.fixed_from);
  for (std::size_t t = 3; t < run.rounds.size(); ++t)
    CHECK(run.rounds[t].counts[2] <= 1);
  CHECK(never_fixed_by_counts(system, run.last));
  // The same line with 2 robots in region 3 only becomes fixed, and no proof is claimed.
  const std::vector<mc::Robot> two{robot(0, {3, 2}, {3, 2}), robot(1, {7, 4}, {3, 2})};
  CHECK(system.run(two, 6).fixed_from);
  CHECK_FALSE(never_fixed_by_counts(system, two));
}

TEST_CASE("theorem 6.9: the random search says 'holds on N samples' and shrinks what it finds",
          "[proofs][theorem-6.9][search]") {
  PositionalFamily f = tiny_positions();
  f.samples = 40;
  f.seed = 3;
  f.sample_max_count = 6;
  f.memberships = {mc::Membership::assigned};
  const TheoremCheck holds = check_theorem_6_9(tiny_counts(), f);
  CHECK(holds.result.verdict == checker::Verdict::incomplete);
  CHECK_THAT(holds.result.message, Catch::StartsWith("holds on 40 samples (a random search"));
  CHECK(holds.runs == 40);
  // The same figures for every thread count.
  const TheoremCheck two = check_theorem_6_9(tiny_counts(), f, {.threads = 2});
  CHECK(two.rounds == holds.rounds);

  f.memberships = {mc::Membership::position};
  const TheoremCheck found = check_theorem_6_9(tiny_counts(), f);
  CHECK(found.result.verdict == checker::Verdict::violated);
  const PositionalTally& fixed = found.claim("6.9(1) fixed [position]");
  REQUIRE(fixed.smallest);
  CHECK_THAT(fixed.smallest->why, Catch::EndsWith("(shrunk)"));
  CHECK(fixed.smallest->robots == fixed.smallest->start.size());
  CHECK(fixed.smallest->robots <= 6);
}
