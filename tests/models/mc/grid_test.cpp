#include <catch2/catch.hpp>

#include "models/mc/grid.hpp"

using mc::GridTiling;
using mc::Neighbourhood;
using mc::RegionId;

TEST_CASE("grid: neighbours in the 4- and 8-neighbourhoods", "[mc][grid]") {
  const GridTiling four(3, Neighbourhood::four), eight(3, Neighbourhood::eight);
  const RegionId centre = four.id(1, 1), corner = four.id(0, 0), edge = four.id(0, 1);
  CHECK(four.nbrs(centre) == std::vector<RegionId>{1, 3, 5, 7});
  CHECK(eight.nbrs(centre) == std::vector<RegionId>{0, 1, 2, 3, 5, 6, 7, 8});
  CHECK(four.nbrs(corner) == std::vector<RegionId>{1, 3});
  CHECK(eight.nbrs(corner) == std::vector<RegionId>{1, 3, 4});
  CHECK(four.nbrs(edge).size() == 3);
  CHECK(eight.nbrs(edge).size() == 5);
  CHECK(eight.nbrs_plus(corner) == std::vector<RegionId>{0, 1, 3, 4});
  CHECK(eight.neighbours(0, 4));
  CHECK_FALSE(four.neighbours(0, 4));
  CHECK(boost::num_edges(four.graph()) == 12);
  CHECK(boost::num_edges(eight.graph()) == 20);
}

TEST_CASE("grid: regDist in closed form agrees with breadth-first search", "[mc][grid]") {
  for (int m = 1; m <= 6; ++m)
    for (const auto nbh : {Neighbourhood::four, Neighbourhood::eight}) {
      const GridTiling grid(m, nbh);
      RegionId diameter = 0;
      for (RegionId u = 0; u < grid.size(); ++u) {
        const auto hops = grid.hops_from(u);
        for (RegionId v = 0; v < grid.size(); ++v) {
          INFO("m=" << m << " nbh=" << static_cast<int>(nbh) << " u=" << u << " v=" << v);
          REQUIRE(grid.reg_dist(u, v) == hops[v]);
          diameter = std::max(diameter, hops[v]);
        }
      }
      CHECK(grid.diameter() == diameter);
      CHECK(grid.diameter() ==
            static_cast<RegionId>(nbh == Neighbourhood::four ? 2 * (m - 1) : m - 1));
    }
}

TEST_CASE("grid: a bad side is rejected", "[mc][grid]") {
  CHECK_THROWS_AS(GridTiling(0, Neighbourhood::four), std::invalid_argument);
}
