#include <catch2/catch.hpp>

#include "checker/checks.hpp"
#include "models/mc/round_automaton.hpp"

using mc::Counts;

namespace {

// Every distribution of 0..n robots per region, as run_to_fixpoint sees them.
void for_each_start(std::size_t regions, mc::RobotCount n,
                    const std::function<void(const Counts&)>& visit) {
  Counts counts(regions, 0);
  std::function<void(std::size_t)> region = [&](std::size_t u) {
    if (u == regions) {
      visit(counts);
      return;
    }
    for (mc::RobotCount c = 0; c <= n; ++c) {
      counts[u] = c;
      region(u + 1);
    }
  };
  region(0);
}

} // namespace

TEST_CASE("mc-round: the worst-case rounds to a fixed point, measured two ways", "[mc][round]") {
  // The stabilisation check on the round automaton (every order of every lower set) and
  // run_to_fixpoint from every start (the default order) must agree on the largest
  // number of rounds before the counts stop changing whenever every round has a single
  // outcome, which the check's edge count (one edge per state) shows.
  for (const auto nbh : {mc::Neighbourhood::four, mc::Neighbourhood::eight}) {
    const mc::GridTiling grid(2, nbh);
    mc::McParams params;
    params.k = 1;
    const mc::RoundSystem system(grid, {1, 3, 0, 0}, params);
    const mc::RobotCount n = 6;
    const auto round = mc::round_automaton(system, n);
    const auto y = round.y;
    const checker::PropertyResult r =
        checker::check_stabilisation(round.automaton,
                                     [&](const tioa::State& s) {
                                       const Counts counts = mc::counts_of(y, s);
                                       return system.next(counts) == counts;
                                     },
                                     {});
    REQUIRE(r.verdict == checker::Verdict::holds);
    REQUIRE(r.edges == r.states); // one outcome per round: the orders do not matter here
    std::size_t worst = 0;
    for_each_start(grid.size(), n, [&](const Counts& start) {
      worst = std::max(worst, system.run_to_fixpoint(start).fixpoint_round);
    });
    CHECK(*r.worst_time == worst);
    CHECK(worst == 3);
  }
}
