// Exact local geometry (models/mc/exact_local_curve.hpp): the refusal of curves without exact
// arc lengths; Γ_u(s), Γ_u⁻¹(x) and the nearest point on hand-computed cases; and a
// cross-check against CurveOnGrid's 100-digit geometry (|A_u|, q, owned ends, inf P_u,
// points, nearest points within 1e-40) on several curves, C1 and C2 among them.
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "models/mc/curve_simulation.hpp"
#include "models/mc/exact_local_curve.hpp"
#include "tests/models/mc/exact_values.hpp"

using namespace mc;
using mc::testing::at;
using mc::testing::frac;
using mc::testing::grid;

namespace {

bool near(const Real& a, const Real& b) {
  return abs(a - b) <= Real("1e-40");
}
bool near(const RationalPoint& a, const Point& b) {
  return near(Real(a.x), b.x) && near(Real(a.y), b.y);
}

std::string refusal(const Curve& curve, int m) {
  try {
    ExactCurve(curve, grid(m), frac(1, 4));
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "accepted";
}

// Every region's exact part against CurveOnGrid, and nearest points of random rational
// points (on a 1/97 lattice, so that exact ties are rare but boundary points occur).
void cross_check(const ExactCurve& exact, std::uint64_t seed) {
  const CurveOnGrid& rounded = exact.on_grid();
  std::mt19937_64 random(seed);
  const long side = 97L * rounded.m();
  for (RegionId u = 0; u < exact.size(); ++u) {
    INFO("region " << u);
    const LocalPart& part = rounded.local(u);
    const ExactLocalPart& mine = exact.local(u);
    REQUIRE(mine.empty == part.empty);
    if (part.empty)
      continue;
    CHECK(mine.length == part.length.rational());
    CHECK(mine.q == part.q);
    CHECK(mine.q == rounded.q(u));
    CHECK(mine.inf_owned == part.inf_owned);
    CHECK(mine.sup_owned == part.sup_owned);
    CHECK(near(Real(mine.inf), part.inf));
    CHECK(near(Real(mine.inf + mine.length), part.sup));
    for (long k = 0; k <= 8; ++k) {
      const Rational s = mine.length * frac(k, 8);
      CHECK(near(exact.point(u, s), rounded.point(u, Real(mine.inf + s))));
      CHECK(exact.parameter(u, exact.point(u, s)).has_value());
    }
    for (int trial = 0; trial < 40; ++trial) {
      const RationalPoint x{frac(static_cast<long>(random() % (side + 1)), 97),
                            frac(static_cast<long>(random() % (side + 1)), 97)};
      const ExactNearest mine_nearest = exact.nearest(u, x);
      const NearestPoint their = rounded.nearest(u, to_point(x));
      CHECK(near(mine_nearest.point, their.point));
      CHECK(near(Real(mine.inf + mine_nearest.parameter), their.parameter));
      CHECK(near(sqrt(Real(mine_nearest.squared_distance)), their.distance));
    }
  }
}

} // namespace

TEST_CASE("exact_curve refuses curves without exact arc lengths", "[exact-curve]") {
  CHECK(refusal(Curve::polyline({at(0, 0), at(1, 0), at(2, 1)}), 2) ==
        "positions need exact arc lengths: segment 1 from (1,0) to (2,1) has length √2");
  CHECK(refusal(Curve::polyline({at(0, 0), at(frac(1, 2), 1)}), 2) ==
        "positions need exact arc lengths: segment 0 from (0,0) to (1/2,1) has length √(5/4)");
  CHECK(refusal(Curve::circle(at(1, 1), frac(1, 2)), 2) ==
        "positions need exact arc lengths: component 0 is a circle (centre (1,1), radius 1/2), "
        "whose arcs have no rational length");
  CHECK(refusal(Curve::annulus(at(3, 3), 1, 2), 6) ==
        "positions need exact arc lengths: component 0 is a circle (centre (3,3), radius 1), "
        "whose arcs have no rational length");
  // 3-4-5 segments and axis-parallel ones are accepted.
  CHECK(refusal(Curve::polyline({at(0, 0), at(frac(9, 5), frac(12, 5)), at(3, frac(12, 5))}), 3) ==
        "accepted");
}

TEST_CASE("exact_curve: a straight line across two regions", "[exact-curve]") {
  // y = 1/2 from x = 0 to x = 2 on a 1×2… here a 2×2 grid: regions 0 and 1 on the top row.
  const ExactCurve gamma(Curve::polyline({at(0, frac(1, 2)), at(2, frac(1, 2))}), grid(2),
                         frac(1, 4));
  CHECK(gamma.meets(0));
  CHECK(gamma.meets(1));
  CHECK_FALSE(gamma.meets(2));
  CHECK(gamma.length(0) == 1);
  CHECK(gamma.local(0).inf == 0);
  CHECK(gamma.local(1).inf == 1);
  // x = 1 belongs to the region east of it: Γ leaves region 0 across a point it does
  // not own.
  CHECK(gamma.local(0).inf_owned);
  CHECK_FALSE(gamma.local(0).sup_owned);
  CHECK(gamma.local(1).inf_owned);
  CHECK(gamma.local(1).sup_owned);
  CHECK(gamma.point(0, 1) == at(1, frac(1, 2)));
  CHECK(gamma.point(1, 0) == at(1, frac(1, 2)));
  CHECK(gamma.point(1, frac(1, 3)) == at(frac(4, 3), frac(1, 2)));
  CHECK_THROWS_AS(gamma.point(0, frac(11, 10)), std::out_of_range);
  CHECK_THROWS_AS(gamma.point(2, 0), std::invalid_argument);
  CHECK(gamma.parameter(0, at(frac(1, 3), frac(1, 2))) == frac(1, 3));
  CHECK(gamma.parameter(0, at(1, frac(1, 2))) == 1); // the closure
  CHECK_FALSE(gamma.parameter(0, at(frac(1, 3), frac(1, 3))).has_value());
  const ExactNearest nearest = gamma.nearest(0, at(frac(1, 3), frac(3, 4)));
  CHECK(nearest.point == at(frac(1, 3), frac(1, 2)));
  CHECK(nearest.parameter == frac(1, 3));
  CHECK(nearest.squared_distance == frac(1, 16));
  // Beyond the end of Γ_0: the end of the closure.
  CHECK(gamma.nearest(0, at(frac(3, 2), 0)).point == at(1, frac(1, 2)));
  CHECK(gamma.region_of(at(1, frac(1, 2))) == 1);
  CHECK(gamma.in_closure(0, at(1, frac(1, 2))));
  CHECK_FALSE(gamma.in_closure(0, at(frac(3, 2), frac(1, 2))));
  cross_check(gamma, 1);
}

TEST_CASE("exact_curve: nearest-point ties go to the smallest parameter", "[exact-curve]") {
  // A corner inside region 0: (1/4,1/4) → (3/4,1/4) → (3/4,3/4). The point (1/2,1/2) is
  // 1/4 from both legs: nearest at (1/2,1/4), s = 1/4, and at (3/4,1/2), s = 3/4.
  const ExactCurve corner(Curve::polyline({at(frac(1, 4), frac(1, 4)), at(frac(3, 4), frac(1, 4)),
                                           at(frac(3, 4), frac(3, 4))}),
                          grid(1), frac(1, 4));
  const ExactNearest nearest = corner.nearest(0, at(frac(1, 2), frac(1, 2)));
  CHECK(nearest.parameter == frac(1, 4));
  CHECK(nearest.point == at(frac(1, 2), frac(1, 4)));
  CHECK(nearest.squared_distance == frac(1, 16));
  // The same rule as CurveOnGrid::nearest.
  CHECK(abs(corner.on_grid().nearest(0, to_point(at(frac(1, 2), frac(1, 2)))).parameter -
            Real(frac(1, 4))) < Real("1e-40"));
  // A closed square inside one region: its start point is at s = 0 and s = |A_u|.
  const ExactCurve square(Curve::rectangle(at(frac(1, 4), frac(1, 4)), at(frac(3, 4), frac(3, 4))),
                          grid(1), frac(1, 4));
  CHECK(square.length(0) == 2);
  CHECK(square.parameter(0, at(frac(1, 4), frac(1, 4))) == 0);
  CHECK(square.point(0, 2) == at(frac(1, 4), frac(1, 4)));
  // The centre is 1/4 from every side: the smallest parameter is on the first side.
  CHECK(square.nearest(0, at(frac(1, 2), frac(1, 2))).point == at(frac(1, 2), frac(1, 4)));
  cross_check(square, 2);
}

TEST_CASE("exact_curve agrees with CurveOnGrid", "[exact-curve]") {
  SECTION("a 3-4-5 segment and an axis-parallel one") {
    cross_check(
        ExactCurve(Curve::polyline({at(0, 0), at(frac(9, 5), frac(12, 5)), at(3, frac(12, 5))}),
                   grid(3), frac(1, 4)),
        3);
  }
  SECTION("a 3-4-5 path through a grid vertex") {
    cross_check(ExactCurve(Curve::polyline({at(frac(1, 4), 0), at(1, 1), at(frac(7, 4), 2)}),
                           grid(2), frac(1, 10)),
                4);
  }
  SECTION("a closed rectangle across four regions, b = 1/2") {
    cross_check(ExactCurve(Curve::rectangle(at(frac(1, 4), frac(1, 4)), at(frac(3, 4), frac(3, 4))),
                           grid(2), frac(1, 8), frac(1, 2)),
                5);
  }
  SECTION("the simulation curves C1 and C2") {
    for (int m = 2; m <= 7; ++m) {
      INFO("m = " << m);
      cross_check(ExactCurve(curve_c1(m), grid(m), frac(1, 4)), 10 + static_cast<unsigned>(m));
      cross_check(ExactCurve(curve_c2(m), grid(m), frac(1, 4)), 20 + static_cast<unsigned>(m));
    }
    const ExactCurve c1(curve_c1(6), grid(6), frac(1, 4));
    CHECK(c1.on_grid().in() == std::vector<RegionId>{21, 22, 23, 27, 29, 33, 34, 35});
    for (RegionId u : c1.on_grid().in())
      CHECK(c1.length(u) == 1);
  }
}
