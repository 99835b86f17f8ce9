// The round-level system over counts (models/mc/round.hpp): one round on a shared
// snapshot, every per-region order choice, conservation, In/Out, and runs to the fixed
// point with T_out and T_stab pinned.
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <random>

#include "models/mc/round.hpp"

using namespace mc;

namespace {

McParams params(RobotCount k, Rational rho2) {
  McParams p;
  p.k = k;
  p.rho2 = std::move(rho2);
  return p;
}

// 3×3, 8-neighbourhood, the curve through (0,0) and (0,1) only; 30 robots start in the
// lower-right corner (a small seed 002 §VII: the curve far from the robots).
RoundSystem corner_system() {
  return RoundSystem(GridTiling(3, Neighbourhood::eight), {1, 1, 0, 0, 0, 0, 0, 0, 0},
                     params(1, Rational(9, 10)));
}
const Counts corner_counts{0, 0, 0, 0, 0, 0, 0, 0, 30};

// The count-level T_out: the first round from which no Out(t) region's count changes.
std::size_t t_out_by_counts(const RoundSystem& system, const FixpointRun& run) {
  std::optional<std::size_t> last;
  for (std::size_t t = 0; t + 1 < run.rounds.size(); ++t)
    for (RegionId h : system.out_regions(run.rounds[t]))
      if (run.rounds[t + 1][h] != run.rounds[t][h])
        last = t;
  return last ? *last + 1 : 0;
}

} // namespace

TEST_CASE("round: every VN runs assign on the same snapshot", "[mc][round]") {
  // 2×2, 4-neighbourhood, no curve, e = 1, ρ2 = 9/10; counts (row by row) 20 10 / 0 0.
  //   region 0: lower = {1, 2}: ⌊0.9·10/6⌋ = 1 to 1, ⌊0.9·20/6⌋ = 3 to 2
  //   region 1: reads y(1) = 10 (not 10 + 1): lower = {3}: ⌊0.9·10/4⌋ = 2 to 3
  const RoundSystem system(GridTiling(2, Neighbourhood::four), {0, 0, 0, 0},
                           params(1, Rational(9, 10)));
  const Counts start{20, 10, 0, 0};
  const Flow flow = system.flow(start);
  CHECK(flow.transfers == std::vector<Transfer>{{0, 1, 1}, {0, 2, 3}, {1, 3, 2}});
  CHECK(flow.at(0, 2) == 3);
  CHECK(flow.at(2, 0) == 0);
  CHECK(flow.sent_by(0) == 4);
  CHECK(flow.received_by(1) == 1);
  CHECK(flow.dense(4)[1][3] == 2);
  CHECK(system.next(start) == Counts{16, 9, 3, 2});
}

TEST_CASE("round: In(t) and Out(t) are the regions with robots on and off the curve",
          "[mc][round]") {
  const RoundSystem system = corner_system();
  const Counts counts{0, 3, 0, 1, 0, 0, 0, 0, 5};
  CHECK(system.in_regions(counts) == std::vector<RegionId>{1});
  CHECK(system.out_regions(counts) == std::vector<RegionId>{3, 8});
  CHECK(system.in_regions(corner_counts).empty());
}

TEST_CASE("round: all_next covers every order of every lower set", "[mc][round]") {
  // 2×2, 4-neighbourhood, e = 3. Region 0 (q = 1, y = 10) has lower = {1, 2} with ideals
  // 4 (q = 4, y = 10) and 6 (q = 5, y = 10) and n − e = 7: order (1, 2) sends 4 and 3,
  // order (2, 1) sends 1 and 6. Regions 1 and 2 have no lower neighbour.
  const RoundSystem system(GridTiling(2, Neighbourhood::four), {1, 4, 5, 0},
                           params(3, Rational(9, 10)));
  const Counts start{10, 10, 10, 0};
  CHECK(system.next(start) == Counts{3, 14, 13, 0}); // the default order: by region id
  const std::vector<Flow> flows = system.all_flows(start);
  REQUIRE(flows.size() == 2);
  CHECK(flows[0].transfers == std::vector<Transfer>{{0, 1, 1}, {0, 2, 6}});
  CHECK(flows[1].transfers == std::vector<Transfer>{{0, 1, 4}, {0, 2, 3}});
  CHECK(system.all_next(start) == std::vector<Counts>{{3, 11, 16, 0}, {3, 14, 13, 0}});

  try {
    (void)system.all_flows(start, 1);
    FAIL("no TooManyOutcomes");
  } catch (const TooManyOutcomes& e) {
    CHECK_THAT(e.what(), Catch::Contains("more than 1 combinations"));
  }
}

TEST_CASE("round: every round conserves the robots", "[mc][round]") {
  std::mt19937_64 random(7);
  auto pick = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(random);
  };
  std::size_t rounds = 0, branching = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int m = static_cast<int>(pick(1, 3));
    const auto nbh = trial % 2 ? Neighbourhood::four : Neighbourhood::eight;
    std::vector<QuantisedLength> q;
    Counts start;
    for (int u = 0; u < m * m; ++u) {
      q.push_back(pick(0, 1) ? pick(1, 4) : 0);
      start.push_back(pick(0, 2) ? pick(0, 60) : 0);
    }
    const RoundSystem system(GridTiling(m, nbh), q, params(pick(1, 4), Rational(pick(1, 9), 10)));
    const FixpointRun run = system.run_to_fixpoint(start);
    REQUIRE(run.rounds.size() == run.fixpoint_round + 1);
    REQUIRE(run.flows.size() == run.fixpoint_round);
    for (std::size_t t = 0; t < run.rounds.size(); ++t) {
      CHECK(total(run.rounds[t]) == total(start));
      const std::vector<Counts> successors = system.all_next(run.rounds[t]);
      for (const Counts& successor : successors)
        CHECK(total(successor) == total(start));
      branching += successors.size() > 1;
      if (t < run.flows.size()) {
        CHECK(run.flows[t].apply(run.rounds[t]) == run.rounds[t + 1]);
        CHECK(std::find(successors.begin(), successors.end(), run.rounds[t + 1]) !=
              successors.end());
      }
    }
    CHECK(system.flow(run.fixpoint()).empty()); // no robot moves at the fixed point
    CHECK(run.t_stab == run.fixpoint_round);
    CHECK(run.t_out <= run.t_stab);
    CHECK(run.t_out == t_out_by_counts(system, run));
    rounds += run.rounds.size();
  }
  CHECK(rounds > 400);
  CHECK(branching > 0); // some rounds have several outcomes
}

TEST_CASE("round: a run to the fixed point with T_out and T_stab", "[mc][round]") {
  SECTION("robots far from the curve: T_out = 7, T_stab = 8") {
    const RoundSystem system = corner_system();
    const FixpointRun run = system.run_to_fixpoint(corner_counts);
    const std::vector<Counts> expected{
        {0, 0, 0, 0, 0, 0, 0, 0, 30}, {0, 0, 0, 0, 3, 3, 0, 3, 21}, {1, 3, 0, 0, 3, 3, 0, 5, 15},
        {2, 6, 0, 0, 2, 2, 0, 6, 12}, {2, 7, 0, 0, 3, 2, 0, 6, 10}, {4, 8, 0, 0, 1, 1, 0, 6, 10},
        {4, 8, 0, 0, 2, 2, 0, 6, 8},  {4, 9, 0, 0, 2, 1, 0, 6, 8},  {5, 8, 0, 0, 2, 1, 0, 6, 8}};
    CHECK(run.rounds == expected);
    CHECK(run.fixpoint_round == 8);
    // Round 6 is the last in which an Out region moves robots ((1,2) → (0,1)); in round 7
    // only (0,1) → (0,0), both on the curve.
    CHECK(run.flows[6].transfers == std::vector<Transfer>{{5, 1, 1}});
    CHECK(run.flows[7].transfers == std::vector<Transfer>{{1, 0, 1}});
    CHECK(run.t_out == 7);
    CHECK(run.t_stab == 8);

    RunOptions lean;
    lean.keep_history = false;
    const FixpointRun short_run = system.run_to_fixpoint(corner_counts, lean);
    CHECK(short_run.rounds == std::vector<Counts>{expected.back()});
    CHECK(short_run.flows.empty());
    CHECK(short_run.t_out == 7);
    CHECK(short_run.t_stab == 8);
  }
  SECTION("robots next to the curve: T_out = 0, T_stab = 4") {
    const RoundSystem system(GridTiling(3, Neighbourhood::eight), {0, 0, 0, 0, 2, 1, 0, 1, 1},
                             params(1, Rational(9, 10)));
    const FixpointRun run = system.run_to_fixpoint({0, 0, 0, 0, 0, 0, 0, 0, 40});
    CHECK(run.rounds == std::vector<Counts>{{0, 0, 0, 0, 0, 0, 0, 0, 40},
                                            {0, 0, 0, 0, 9, 4, 0, 4, 23},
                                            {0, 0, 0, 0, 13, 6, 0, 6, 15},
                                            {0, 0, 0, 0, 14, 7, 0, 7, 12},
                                            {0, 0, 0, 0, 15, 7, 0, 7, 11}});
    CHECK(run.t_out == 0);
    CHECK(run.t_stab == 4);
  }
  SECTION("a fixed point from the start") {
    const RoundSystem system = corner_system();
    const FixpointRun run = system.run_to_fixpoint({1, 1, 0, 0, 0, 0, 0, 0, 1});
    CHECK(run.rounds.size() == 1);
    CHECK(run.t_out == 0);
    CHECK(run.t_stab == 0);
  }
}

TEST_CASE("round: the round limit", "[mc][round]") {
  const RoundSystem system = corner_system();
  RunOptions options;
  options.max_rounds = 8; // the fixed point is M8: enough
  CHECK(system.run_to_fixpoint(corner_counts, options).fixpoint_round == 8);
  options.max_rounds = 7;
  try {
    (void)system.run_to_fixpoint(corner_counts, options);
    FAIL("no RoundLimitReached");
  } catch (const RoundLimitReached& e) {
    CHECK(e.rounds == 7);
    CHECK_THAT(e.what(), Catch::Contains("no fixed point within 7 rounds"));
  }
}

TEST_CASE("round: bad input throws", "[mc][round]") {
  const GridTiling grid(2, Neighbourhood::four);
  CHECK_THROWS_AS(RoundSystem(grid, {0, 0, 0}, McParams{}), std::invalid_argument);
  CHECK_THROWS_AS(RoundSystem(grid, {0, -1, 0, 0}, McParams{}), std::invalid_argument);
  McParams bad_rho1;
  bad_rho1.rho1 = 1;
  CHECK_THROWS_AS(RoundSystem(grid, {0, 0, 0, 0}, bad_rho1), std::invalid_argument);
  CHECK_THROWS_AS(RoundSystem(grid, {0, 0, 0, 0}, params(1, Rational(3, 2))),
                  std::invalid_argument);
  const RoundSystem system(grid, {0, 0, 0, 0}, McParams{});
  CHECK_THROWS_AS(system.next({1, 2, 3}), std::invalid_argument);
  CHECK_THROWS_AS(system.next({1, 2, 3, -4}), std::invalid_argument);
  CHECK_THROWS_AS(system.next({max_robots, 1, 0, 0}), std::invalid_argument);
}
