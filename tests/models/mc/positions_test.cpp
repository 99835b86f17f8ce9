// The positional round system (models/mc/positions.hpp): calctarget line by line on
// hand-computed cases, robots sent to centres, nearest-point ties, exact positions after
// a few rounds; counts under Membership::assigned equal RoundSystem's; convergence to even
// spacing; and the finding: under Membership::position the assignment need never become
// fixed (robots that calctarget sends to an end of Γ_h owned by the next region).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "models/mc/curve_simulation.hpp"
#include "models/mc/positions.hpp"
#include "models/mc/spacing.hpp"
#include "tests/models/mc/exact_values.hpp"

using namespace mc;
using mc::testing::at;
using mc::testing::frac;
using mc::testing::grid;

namespace {

Robot robot(RobotId id, Rational x, Rational y) {
  return {id, at(std::move(x), std::move(y)), std::nullopt};
}

// y = 1/2 across the top row of a 2×2 grid, from west to east: Γ leaves region 0 at
// (1, 1/2), which region 1 owns (sup_owned false for region 0).
ExactCurve eastward() {
  return ExactCurve(Curve::polyline({at(0, frac(1, 2)), at(2, frac(1, 2))}), grid(2), frac(1, 4));
}
// The same line from east to west: Γ enters region 0 at (1, 1/2), owned by region 1
// (inf_owned false for region 0).
ExactCurve westward() {
  return ExactCurve(Curve::polyline({at(2, frac(1, 2)), at(0, frac(1, 2))}), grid(2), frac(1, 4));
}

PositionSystem system_on(ExactCurve curve, Membership membership = Membership::position,
                         RobotCount k = 1) {
  return PositionSystem(std::move(curve), McParams{k, frac(1, 2), frac(9, 10)},
                        PositionOptions{membership, Reassignment::lowest_ids, 0});
}

std::vector<Counts> counts_of(const PositionRun& run) {
  std::vector<Counts> counts;
  for (const PositionRound& round : run.rounds)
    counts.push_back(round.counts);
  return counts;
}

} // namespace

TEST_CASE("calctarget, line by line", "[positions]") {
  const PositionSystem system = system_on(eastward());
  // VN_1: Γ_1 from (1,1/2) (s = 0) to (2,1/2) (s = 1).
  const std::vector<Robot> members{
      robot(3, frac(5, 4), frac(1, 2)), // on Γ_1, s = 1/4: the middle of seq
      robot(4, 2, frac(1, 2)),          // s = 1: the last of seq
      robot(5, 1, frac(1, 2)),          // s = 0: the first of seq
      robot(6, frac(3, 2), frac(3, 4)), // off Γ_1
      robot(7, frac(7, 4), 1),          // reassigned to region 0
  };
  const std::vector<Target> targets = system.calctarget(1, members, {1, 1, 1, 1, 0});
  REQUIRE(targets.size() == 5);
  // line 38: 1/4 + 1/2·((0 + 1)/2 − 1/4) = 3/8
  CHECK(targets[0] == Target{3, 1, at(frac(11, 8), frac(1, 2)), TargetRule::spacing});
  CHECK(targets[1] == Target{4, 1, at(2, frac(1, 2)), TargetRule::last});             // line 36
  CHECK(targets[2] == Target{5, 1, at(1, frac(1, 2)), TargetRule::first});            // line 35
  CHECK(targets[3] == Target{6, 1, at(frac(3, 2), frac(1, 2)), TargetRule::nearest}); // line 33
  CHECK(targets[4] == Target{7, 0, at(frac(1, 2), frac(1, 2)), TargetRule::centre});  // line 31

  // seq is sorted by p, then id: two robots at the same point.
  const std::vector<Target> tied = system.calctarget(
      1, {robot(2, frac(3, 2), frac(1, 2)), robot(9, frac(3, 2), frac(1, 2))}, {1, 1});
  CHECK(tied[0].rule == TargetRule::first);
  CHECK(tied[1].rule == TargetRule::last);
  // A single robot is first (line 35 before line 36).
  CHECK(system.calctarget(1, {robot(2, frac(3, 2), frac(1, 2))}, {1})[0] ==
        Target{2, 1, at(1, frac(1, 2)), TargetRule::first});
  // A region off the curve: the robot keeps its position (our decision).
  CHECK(system.calctarget(2, {robot(1, frac(1, 3), frac(3, 2))}, {2})[0] ==
        Target{1, 2, at(frac(1, 3), frac(3, 2)), TargetRule::off_curve});
  // Region 0 in the faithful reading's trouble: its last robot goes to (1, 1/2), which
  // region 1 owns.
  CHECK(system.calctarget(0, {robot(1, 0, frac(1, 2)), robot(2, frac(1, 2), frac(1, 2))}, {0, 0})[1]
            .position == at(1, frac(1, 2)));
}

TEST_CASE("calctarget: nearest-point ties go to the smallest parameter", "[positions]") {
  // The corner (1/4,1/4) → (3/4,1/4) → (3/4,3/4): (1/2,1/2) is 1/4 from both legs.
  const PositionSystem system =
      system_on(ExactCurve(Curve::polyline({at(frac(1, 4), frac(1, 4)), at(frac(3, 4), frac(1, 4)),
                                            at(frac(3, 4), frac(3, 4))}),
                           grid(1), frac(1, 4)));
  CHECK(system.calctarget(0, {robot(0, frac(1, 2), frac(1, 2))}, {0})[0] ==
        Target{0, 0, at(frac(1, 2), frac(1, 4)), TargetRule::nearest});
}

TEST_CASE("a round: assign's flow, robots sent to centres by lowest id", "[positions]") {
  const PositionSystem system = system_on(westward());
  // Six robots in region 1, none in region 0: assign sends ⌊0.9·6/4⌋ = 1 to region 0.
  std::vector<Robot> robots;
  for (RobotId i = 0; i < 6; ++i)
    robots.push_back(robot(i, 1 + frac(static_cast<long>(i), 5), frac(1, 2)));
  const PositionRound round = system.round(robots);
  CHECK(round.counts == Counts{0, 6, 0, 0});
  CHECK(round.flow == Flow{{Transfer{1, 0, 1}}});
  CHECK(round.reassigned == std::vector<Move>{{0, 1, 0}});
  CHECK(round.targets[0] == Target{0, 0, at(frac(1, 2), frac(1, 2)), TargetRule::centre});
  // Region 1 (s from (2,1/2) westward): robot 5 at x = 2 is first, robot 1 at x = 6/5
  // last; robots 2–4 move by line 38 (spacing_step on s = 3/5, 2/5, 1/5).
  CHECK(round.targets[5].position == at(2, frac(1, 2)));
  CHECK(round.targets[1].position == at(1, frac(1, 2)));
  CHECK(round.targets[3].position == at(frac(8, 5), frac(1, 2)));
  CHECK(round.migrations.empty());
  const std::vector<Robot> after = PositionSystem::after(round);
  CHECK(after[0].assigned == RegionId{0});
  CHECK(after[1].assigned == RegionId{1});
}

TEST_CASE("exact positions after a few rounds on a straight line", "[positions]") {
  // One region, y = 1/2 from x = 0 to x = 1 (m = 1: the region owns both ends).
  const PositionSystem system = system_on(
      ExactCurve(Curve::polyline({at(0, frac(1, 2)), at(1, frac(1, 2))}), grid(1), frac(1, 4)));
  const PositionRun run = system.run({robot(0, 0, frac(1, 2)), robot(1, frac(1, 10), frac(1, 2)),
                                      robot(2, frac(1, 5), frac(1, 2)), robot(3, 1, frac(1, 2))},
                                     2);
  // Round 0: 0, 1/10 + 1/2·(1/10 − 1/10), 1/5 + 1/2·(11/20 − 1/5) = 3/8, 1.
  CHECK(run.rounds[1].robots[1].position.x == frac(1, 10));
  CHECK(run.rounds[1].robots[2].position.x == frac(3, 8));
  // Round 1: 1/10 + 1/2·(3/16 − 1/10) = 23/160, 3/8 + 1/2·(11/20 − 3/8) = 37/80.
  CHECK(run.last[0].position == at(0, frac(1, 2)));
  CHECK(run.last[1].position == at(frac(23, 160), frac(1, 2)));
  CHECK(run.last[2].position == at(frac(37, 80), frac(1, 2)));
  CHECK(run.last[3].position == at(1, frac(1, 2)));
  CHECK(run.fixed_from == std::size_t{0});
}

TEST_CASE("under Membership::assigned the counts are RoundSystem's", "[positions]") {
  std::mt19937_64 random(7);
  const std::vector<ExactCurve> curves{
      eastward(),
      westward(),
      ExactCurve(curve_c1(3), grid(3), frac(1, 4)),
      ExactCurve(curve_c2(4), grid(4, Neighbourhood::eight), frac(1, 4)),
      ExactCurve(Curve::polyline({at(0, 0), at(frac(9, 5), frac(12, 5)), at(3, frac(12, 5))}),
                 grid(3), frac(1, 5)),
  };
  for (std::size_t c = 0; c < curves.size(); ++c)
    for (int trial = 0; trial < 6; ++trial) {
      const RobotCount k = 1 + trial % 2;
      const Reassignment rule = trial % 3 == 0 ? Reassignment::random : Reassignment::lowest_ids;
      const PositionSystem system(curves[c], McParams{k, frac(1, 2), frac(9, 10)},
                                  PositionOptions{Membership::assigned, rule, 99});
      const long side = 8L * curves[c].grid().m();
      std::vector<Robot> robots;
      const auto n = static_cast<RobotId>(1 + random() % 14);
      for (RobotId i = 0; i < n; ++i)
        robots.push_back(
            robot(i, frac(static_cast<long>(random() % static_cast<unsigned long>(side + 1)), 8),
                  frac(static_cast<long>(random() % static_cast<unsigned long>(side + 1)), 8)));
      const PositionRun run = system.run(robots, 10);
      const FixpointRun counts = system.counts().run_to_fixpoint(run.rounds[0].counts);
      INFO("curve " << c << ", trial " << trial);
      for (std::size_t t = 0; t < run.rounds.size(); ++t) {
        CHECK(run.rounds[t].counts == counts.rounds[std::min(t, counts.fixpoint_round)]);
        CHECK(run.rounds[t].migrations.empty());
      }
      if (counts.fixpoint_round < 10)
        CHECK(run.fixed_from == counts.fixpoint_round);
    }
}

TEST_CASE("the reassignment rule changes positions, not counts", "[positions]") {
  const auto run_with = [](Reassignment rule, std::uint64_t seed) {
    const PositionSystem system(westward(), McParams{1, frac(1, 2), frac(9, 10)},
                                PositionOptions{Membership::position, rule, seed});
    std::vector<Robot> robots;
    for (RobotId i = 0; i < 12; ++i)
      robots.push_back(robot(i, 1 + frac(static_cast<long>(i), 12), frac(1, 2)));
    return system.run(robots, 6);
  };
  const PositionRun lowest = run_with(Reassignment::lowest_ids, 0);
  const PositionRun random = run_with(Reassignment::random, 3);
  CHECK(counts_of(lowest) == counts_of(random));
  CHECK(lowest.last != random.last);
  CHECK(run_with(Reassignment::random, 3).last == random.last); // reproducible
}

TEST_CASE("after the assignment is fixed, positions converge to even spacing", "[positions]") {
  // Both readings on the eastward line, with one robot in region 0 (whose sup it does not
  // own) and four in region 1: assign moves nobody, and nobody migrates.
  for (Membership membership : {Membership::position, Membership::assigned}) {
    const PositionSystem system = system_on(eastward(), membership);
    std::vector<Robot> robots{robot(0, frac(1, 3), frac(1, 5))};
    for (RobotId i = 1; i <= 4; ++i)
      robots.push_back(robot(i, frac(3, 2) + frac(static_cast<long>(i), 10), frac(7, 8)));
    const PositionRun run = system.run(robots, 40);
    CHECK(run.fixed_from == std::size_t{0});
    // Region 1's robots by parameter: the ends fixed, the interior within 1/1000 of
    // 1/3 and 2/3 after 40 rounds (the error shrinks by T each round).
    std::vector<Rational> xs;
    for (RobotId i = 1; i <= 4; ++i)
      xs.push_back(run.last[i].position.x - 1);
    std::sort(xs.begin(), xs.end());
    const std::vector<Rational> even = even_spacing(4, 0, 1);
    CHECK(xs.front() == 0);
    CHECK(xs.back() == 1);
    for (std::size_t i = 0; i < 4; ++i)
      CHECK(abs(xs[i] - even[i]) < frac(1, 1000));
    CHECK(run.last[0].position == at(0, frac(1, 2)));
  }
  // With two robots in region 0 the faithful reading moves one to region 1, and then the
  // assignment is fixed with 1 and 3 where RoundSystem's fixed point keeps 2 and 2.
  const PositionSystem faithful = system_on(eastward());
  const PositionRun run =
      faithful.run({robot(0, frac(1, 4), frac(1, 2)), robot(1, frac(1, 2), frac(1, 2)),
                    robot(2, frac(5, 4), frac(1, 2)), robot(3, frac(3, 2), frac(1, 2))},
                   4);
  CHECK(run.rounds[0].migrations == std::vector<Move>{{1, 0, 1}});
  CHECK(run.fixed_from == std::size_t{1});
  CHECK(run.rounds[1].counts == Counts{1, 3, 0, 0});
  CHECK(faithful.counts().run_to_fixpoint({2, 2, 0, 0}).fixpoint() == Counts{2, 2, 0, 0});
}

// FINDING (seed 000 Theorem 6.9(1), Lemma 6.8; seed 002 Lemmas 4 and 7 read with seed 002
// line 111's membership): the assignment need never become fixed. calctarget's line 35 or
// 36 sends a robot of VN_h to an end of Γ_h that the next region owns; there it reports to
// the next region's VN, and assign sends a robot back, forever.
TEST_CASE("finding: under Membership::position the assignment can stay unfixed forever",
          "[positions]") {
  SECTION("the smallest: 2 robots, Γ from (1,1/2) west to (1/2,1/2) on 2×2") {
    // Region 1 owns only the point (1,1/2): A_1 a point, q_1 = 0, region 1 in Out with
    // In_1 = {0}. Γ_0 = (1,1/2) → (1/2,1/2), inf not owned by region 0.
    const PositionSystem system = system_on(ExactCurve(
        Curve::polyline({at(1, frac(1, 2)), at(frac(1, 2), frac(1, 2))}), grid(2), frac(1, 4)));
    const PositionRun run =
        system.run({robot(0, frac(3, 4), frac(1, 2)), robot(1, 1, frac(1, 2))}, 6);
    // round 0: 1 1 0 0 — #0, alone in region 0, is first of seq and goes to Γ_0(inf P_0) =
    //          (1,1/2), which region 1 owns: migration 0 → 1.
    // round 1: 0 2 0 0 — region 1 (Out, y = 2 > k) sends ⌊(2 − 1)/|In|⌋ = 1 robot to region
    //          0 (line 20), #0 to o_0 = (1/2,1/2).
    // round 2 = round 0 with #0 at (1/2,1/2); round 3 = round 1 exactly: the whole state
    // repeats with period 2, so the assignment never becomes fixed.
    CHECK(counts_of(run) ==
          std::vector<Counts>{
              {1, 1, 0, 0}, {0, 2, 0, 0}, {1, 1, 0, 0}, {0, 2, 0, 0}, {1, 1, 0, 0}, {0, 2, 0, 0}});
    CHECK(run.rounds[0].migrations == std::vector<Move>{{0, 0, 1}});
    CHECK(run.rounds[1].reassigned == std::vector<Move>{{0, 1, 0}});
    CHECK(run.rounds[2].migrations == std::vector<Move>{{0, 0, 1}});
    CHECK(run.rounds[3].robots == run.rounds[1].robots);
    CHECK_FALSE(run.fixed_from.has_value());
    // RoundSystem (counts only) and the other reading: fixed at once.
    CHECK(system.counts().next({1, 1, 0, 0}) == Counts{1, 1, 0, 0});
    const PositionSystem assigned =
        system_on(ExactCurve(Curve::polyline({at(1, frac(1, 2)), at(frac(1, 2), frac(1, 2))}),
                             grid(2), frac(1, 4)),
                  Membership::assigned);
    CHECK(assigned.run({robot(0, frac(3, 4), frac(1, 2)), robot(1, 1, frac(1, 2))}, 3).fixed_from ==
          std::size_t{0});
  }
  SECTION("both regions on the curve: 5 robots on the westward line") {
    // Counts alternate (0,5) → (1,4) → (0,5): at (0,5) VN_1 sends ⌊0.9·5/4⌋ = 1 robot to
    // o_0, which lies on Γ_0; at (1,4) assign moves nobody (⌊0.9·3/4⌋ = 0) and region 0's
    // lone robot goes to Γ_0(inf P_0) = (1,1/2), owned by region 1. Both steps hold
    // whatever the positions in region 1, so the cycle never ends.
    const PositionSystem system = system_on(westward());
    std::vector<Robot> robots;
    for (RobotId i = 0; i < 5; ++i)
      robots.push_back(robot(i, 1 + frac(static_cast<long>(i), 5), frac(1, 2)));
    const PositionRun run = system.run(robots, 30);
    for (std::size_t t = 0; t < run.rounds.size(); ++t) {
      INFO("round " << t);
      CHECK(run.rounds[t].counts == (t % 2 == 0 ? Counts{0, 5, 0, 0} : Counts{1, 4, 0, 0}));
      CHECK(run.rounds[t].migrations.size() == t % 2);
      CHECK(run.rounds[t].flow.empty() == (t % 2 == 1));
    }
    CHECK_FALSE(run.fixed_from.has_value());
    // RoundSystem's fixed point from (0,5) is (1,4); under Membership::assigned the
    // positional system reaches it and stays.
    CHECK(system.counts().run_to_fixpoint({0, 5, 0, 0}).fixpoint() == Counts{1, 4, 0, 0});
    CHECK(system_on(westward(), Membership::assigned).run(robots, 4).fixed_from == std::size_t{1});
  }
  SECTION("4 robots or fewer on the westward line become fixed, from every split") {
    const PositionSystem system = system_on(westward());
    for (RobotId n = 1; n <= 4; ++n)
      for (RobotId west = 0; west <= n; ++west) {
        std::vector<Robot> robots;
        for (RobotId i = 0; i < n; ++i)
          robots.push_back(i < west ? robot(i, frac(static_cast<long>(i + 1), 8), frac(1, 3))
                                    : robot(i, 1 + frac(static_cast<long>(i), 5), frac(2, 3)));
        INFO(n << " robots, " << west << " in region 0");
        CHECK(system.run(robots, 8).fixed_from.has_value());
      }
  }
  SECTION("the eastward line needs 7: (1,6) -> (2,5) -> (1,6)") {
    const PositionSystem system = system_on(eastward());
    std::vector<Robot> robots{robot(0, frac(1, 4), frac(1, 2))};
    for (RobotId i = 1; i < 7; ++i)
      robots.push_back(robot(i, 1 + frac(static_cast<long>(i), 6), frac(1, 2)));
    const PositionRun run = system.run(robots, 12);
    for (std::size_t t = 0; t < run.rounds.size(); ++t)
      CHECK(run.rounds[t].counts == (t % 2 == 0 ? Counts{1, 6, 0, 0} : Counts{2, 5, 0, 0}));
    CHECK_FALSE(run.fixed_from.has_value());
  }
}
