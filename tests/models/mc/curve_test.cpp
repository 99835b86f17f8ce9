// The curve Γ on the grid tiling (models/mc/curve*.hpp): local parts, |A_u|, q_u, In and
// Out on small hand-computed curves; the ownership rule for boundary points; the check of
// seed 000 §5.1's assumption that each A_u is an interval; exact ceilings; Γ_u, Γ_u⁻¹ and
// the nearest point; the simulation curves C1, C2, C3 of seed 002 §VII.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "models/mc/curve_local.hpp"
#include "models/mc/curve_simulation.hpp"
#include "tests/models/mc/exact_values.hpp"

using namespace mc;
using mc::testing::at;
using mc::testing::frac;
using mc::testing::grid;

namespace {

bool close(const Real& a, const Real& b, const Real& tolerance = Real("1e-60")) {
  return abs(a - b) <= tolerance;
}

bool close(const Point& a, const Point& b) {
  return close(a.x, b.x) && close(a.y, b.y);
}

Point real_point(double x, double y) {
  return {Real(x), Real(y)};
}

const Real pi = boost::math::constants::pi<Real>();

} // namespace

TEST_CASE("region_of: half-open squares, the far sides of the square to the last row and "
          "column",
          "[mc][curve]") {
  const CurveOnGrid on_grid(Curve::polyline({at(frac(1, 2), frac(1, 2)), at(frac(1), frac(1, 2))}),
                            grid(3), frac(1, 4));
  CHECK(on_grid.region_of(at(0, 0)) == 0);
  CHECK(on_grid.region_of(at(1, frac(1, 2))) == 1); // vertical line: the region east of it
  CHECK(on_grid.region_of(at(frac(1, 2), 1)) == 3); // horizontal line: the region south of it
  CHECK(on_grid.region_of(at(1, 1)) == 4);          // grid vertex: south-east
  CHECK(on_grid.region_of(at(3, 0)) == 2);          // far side x = m·b: last column
  CHECK(on_grid.region_of(at(3, 3)) == 8);
  CHECK(on_grid.region_of(at(frac(5, 2), 3)) == 8);
  CHECK(on_grid.region_of(real_point(1.25, 2.75)) == 7);
  CHECK(on_grid.centre(5) == at(frac(5, 2), frac(3, 2)));
}

TEST_CASE("2x2: a horizontal segment across one boundary", "[mc][curve]") {
  const CurveOnGrid g(Curve::polyline({at(frac(1, 2), frac(1, 2)), at(frac(3, 2), frac(1, 2))}),
                      grid(2), frac(1, 4));
  CHECK(g.q() == std::vector<std::int64_t>{2, 2, 0, 0});
  CHECK(g.in() == std::vector<RegionId>{0, 1});
  CHECK(g.out() == std::vector<RegionId>{2, 3});
  CHECK(g.q_min() == 2);
  CHECK(g.q_max() == 2);
  const LocalPart& left = g.local(0);
  CHECK(left.length.exact());
  CHECK(left.length.rational() == frac(1, 2));
  CHECK(close(left.inf, 0));
  CHECK(close(left.sup, Real("0.5")));
  CHECK(left.inf_owned);
  CHECK_FALSE(left.sup_owned); // (1, 1/2) lies on x = 1 and belongs to region 1
  const LocalPart& right = g.local(1);
  CHECK(close(right.inf, Real("0.5")));
  CHECK(close(right.sup, 1));
  CHECK(right.inf_owned);
  CHECK(right.sup_owned);
  CHECK(g.local(2).empty);
  CHECK(g.q_matrix() == std::vector<std::vector<std::int64_t>>{{2, 2}, {0, 0}});
}

TEST_CASE("3x3: an L-shaped open polyline", "[mc][curve]") {
  // (1/2,1/2) → (5/2,1/2) → (5/2,5/2), σ = 1/2: 1/2 in regions 0 and 8, 1 in 1, 2 and 5
  // (region 2 holds the corner: 1/2 across and 1/2 down).
  const CurveOnGrid g(Curve::polyline({at(frac(1, 2), frac(1, 2)), at(frac(5, 2), frac(1, 2)),
                                       at(frac(5, 2), frac(5, 2))}),
                      grid(3), frac(1, 2));
  CHECK(g.q_matrix() == std::vector<std::vector<std::int64_t>>{{1, 2, 2}, {0, 0, 2}, {0, 0, 1}});
  CHECK(g.in() == std::vector<RegionId>{0, 1, 2, 5, 8});
  CHECK(g.out() == std::vector<RegionId>{3, 4, 6, 7});
  CHECK(g.q_min() == 1);
  CHECK(g.q_max() == 2);
  CHECK(g.local(2).length.rational() == 1);
  CHECK(close(g.local(2).inf, Real("1.5")));
  CHECK(close(g.local(2).sup, Real("2.5")));
  CHECK(close(g.local(8).sup, 4));
  CHECK(g.local(8).sup_owned); // the end of an open curve
  CHECK(g.format_q() == "1 2 2\n. . 2\n. . 1\n");
}

TEST_CASE("3x3: a closed rectangle gets its origin where it enters a region", "[mc][curve]") {
  // The natural start (1/2,1/2) is in the middle of region 0's stretch; Γ starts instead
  // at (1,1/2), where the curve enters region 1, so that every P_u is an interval.
  const CurveOnGrid g(Curve::rectangle(at(frac(1, 2), frac(1, 2)), at(frac(5, 2), frac(5, 2))),
                      grid(3), frac(1, 2));
  CHECK(g.q_matrix() == std::vector<std::vector<std::int64_t>>{{2, 2, 2}, {2, 0, 2}, {2, 2, 2}});
  CHECK(g.out() == std::vector<RegionId>{4});
  CHECK(close(g.origin(0), Real("0.5")));
  CHECK(close(g.point(0), to_point(at(1, frac(1, 2)))));
  // region: [inf, sup], whether Γ(inf), Γ(sup) are owned (clockwise on the screen)
  struct Expected {
    RegionId u;
    int inf, sup;
    bool inf_owned, sup_owned;
  };
  for (const Expected& e : std::vector<Expected>{{1, 0, 1, true, false},
                                                 {2, 1, 2, true, false},
                                                 {5, 2, 3, true, false},
                                                 {8, 3, 4, true, true},
                                                 {7, 4, 5, false, true},
                                                 {6, 5, 6, false, true},
                                                 {3, 6, 7, false, true},
                                                 {0, 7, 8, false, false}}) {
    INFO("region " << e.u);
    const LocalPart& part = g.local(e.u);
    CHECK(close(part.inf, e.inf));
    CHECK(close(part.sup, e.sup));
    CHECK(part.inf_owned == e.inf_owned);
    CHECK(part.sup_owned == e.sup_owned);
    CHECK(part.length.rational() == 1);
  }
  CHECK_THROWS_AS(g.point(Real(8)), std::out_of_range); // the domain is [0, 8)
  // Region 0's part wraps around the natural start (1/2,1/2) of the polyline.
  const auto wrapped = g.parameter(0, to_point(at(frac(3, 4), frac(1, 2))));
  REQUIRE(wrapped);
  CHECK(close(*wrapped, Real("7.75")));
  CHECK(close(g.point(0, Real(7)), to_point(at(frac(1, 2), 1))));
  CHECK(close(g.nearest(0, to_point(at(0, 0))).parameter, Real("7.5")));
}

TEST_CASE("boundary points: segments along grid lines and through a grid vertex", "[mc][curve]") {
  SECTION("along the vertical line x = 1: the regions east of it") {
    const CurveOnGrid g(Curve::polyline({at(1, frac(1, 4)), at(1, frac(7, 4))}), grid(2),
                        frac(1, 4));
    CHECK(g.q() == std::vector<std::int64_t>{0, 3, 0, 3});
    CHECK(g.local(0).empty);
    CHECK(g.local(1).length.rational() == frac(3, 4));
  }
  SECTION("along the horizontal line y = 1: the regions south of it") {
    const CurveOnGrid g(Curve::polyline({at(frac(1, 4), 1), at(frac(7, 4), 1)}), grid(2),
                        frac(1, 4));
    CHECK(g.q() == std::vector<std::int64_t>{0, 0, 3, 3});
  }
  SECTION("through the vertex (1,1): a single point of region 3") {
    // From region 2 (lower left) to region 1 (upper right); the vertex belongs to region 3.
    const CurveOnGrid g(Curve::polyline({at(frac(1, 2), frac(3, 2)), at(frac(3, 2), frac(1, 2))}),
                        grid(2), frac(1, 4));
    CHECK(g.q() == std::vector<std::int64_t>{0, 3, 3, 0}); // ⌈(√2/2)/(1/4)⌉ = ⌈2.83⌉
    CHECK(g.in() == std::vector<RegionId>{1, 2});
    const LocalPart& vertex = g.local(3);
    CHECK_FALSE(vertex.empty);
    CHECK(vertex.length.zero());
    CHECK(vertex.q == 0);
    CHECK(close(vertex.inf, vertex.sup));
    CHECK(close(vertex.inf, sqrt(Real(2)) / 2));
    CHECK(vertex.inf_owned);
    CHECK_FALSE(g.local(2).sup_owned);
    CHECK_FALSE(g.local(1).inf_owned);
    CHECK_FALSE(g.local(1).length.exact());
    CHECK(close(g.local(1).length.value(), sqrt(Real(2)) / 2));
  }
}

TEST_CASE("a curve that enters a region twice is rejected, naming the region", "[mc][curve]") {
  // Region 0 → region 2 → region 0 again.
  const Curve twice = Curve::polyline({at(frac(1, 4), frac(1, 4)), at(frac(3, 4), frac(1, 4)),
                                       at(frac(3, 4), frac(3, 2)), at(frac(1, 4), frac(3, 2)),
                                       at(frac(1, 4), frac(3, 4))});
  CHECK_THROWS_AS(CurveOnGrid(twice, grid(2), frac(1, 4)), std::invalid_argument);
  CHECK_THROWS_WITH(CurveOnGrid(twice, grid(2), frac(1, 4)),
                    Catch::Contains("enters region 0 (row 0, col 0) more than once"));
  // The same curve in the one region of a 1×1 grid of side b = 2 is fine.
  CHECK(CurveOnGrid(twice, grid(1), frac(1, 4), 2).in() == std::vector<RegionId>{0});

  SECTION("two components in one region") {
    const Curve rings = Curve::annulus(at(1, 1), frac(1, 4), frac(1, 2));
    // The inner circle takes all four regions; the outer one then meets region 3 first.
    CHECK_THROWS_WITH(CurveOnGrid(rings, grid(2), frac(1, 4)),
                      Catch::Contains("meets region 3 (row 1, col 1) with components 0 and 1"));
  }
  SECTION("a circle touching two grid lines from inside its region") {
    // The circle in the middle region of 3×3 touches x = 2 and y = 2; those two points
    // belong to regions 5 and 7 and cut region 4's part in two.
    CHECK_THROWS_WITH(
        CurveOnGrid(Curve::circle(at(frac(3, 2), frac(3, 2)), frac(1, 2)), grid(3), frac(1, 4)),
        Catch::Contains("enters region 4 (row 1, col 1) more than once"));
  }
}

TEST_CASE("tangent circles: a touching point belongs to the region the rule says", "[mc][curve]") {
  SECTION("touching x = 1 from the east: the point stays in the circle's region") {
    const CurveOnGrid g(Curve::circle(at(frac(7, 5), frac(3, 2)), frac(2, 5)), grid(3),
                        frac(1, 10));
    CHECK(g.in() == std::vector<RegionId>{4});
    CHECK(g.local(3).empty);
    CHECK(g.q(4) == 26); // ⌈2π·(2/5)/(1/10)⌉ = ⌈8π⌉
  }
  SECTION("touching x = 2 from the west: a single point of region 5") {
    const CurveOnGrid g(Curve::circle(at(frac(8, 5), frac(3, 2)), frac(2, 5)), grid(3),
                        frac(1, 10));
    CHECK(g.in() == std::vector<RegionId>{4});
    CHECK_FALSE(g.local(5).empty);
    CHECK(g.local(5).q == 0);
    CHECK(close(g.local(5).inf, 0)); // Γ starts at the touching point (2, 3/2)
    CHECK(close(g.point(0), to_point(at(2, frac(3, 2)))));
    CHECK_FALSE(g.local(4).inf_owned);
    CHECK_FALSE(g.local(4).sup_owned);
    CHECK(close(g.local(4).sup, 2 * pi * Real(frac(2, 5))));
  }
}

TEST_CASE("exact ceilings: rational lengths are never rounded", "[mc][curve]") {
  SECTION("1/10 + 2/10 in one region with σ = 1/10 is 3σ: q = 3") {
    const CurveOnGrid g(Curve::polyline({at(frac(1, 10), frac(1, 2)), at(frac(2, 10), frac(1, 2)),
                                         at(frac(2, 10), frac(7, 10))}),
                        grid(1), frac(1, 10));
    CHECK(g.local(0).length.exact());
    CHECK(g.local(0).length.rational() == frac(3, 10));
    CHECK(g.q(0) == 3);
    // What double arithmetic would have said.
    CHECK(std::ceil((0.1 + 0.2) / 0.1) == 4.0);
  }
  SECTION("an axis-parallel segment of exactly 3σ") {
    const CurveOnGrid g(Curve::polyline({at(0, frac(1, 2)), at(frac(3, 4), frac(1, 2))}), grid(1),
                        frac(1, 4));
    CHECK(g.q(0) == 3);
  }
  SECTION("an oblique 3-4-5 segment: length 1/2 exactly, 5σ") {
    const CurveOnGrid g(
        Curve::polyline({at(frac(1, 10), frac(1, 10)), at(frac(4, 10), frac(5, 10))}), grid(1),
        frac(1, 10));
    CHECK(g.local(0).length.exact());
    CHECK(g.local(0).length.rational() == frac(1, 2));
    CHECK(g.q(0) == 5);
  }
  SECTION("an irrational length: √2/2 with σ = 1/10") {
    const CurveOnGrid g(Curve::polyline({at(0, 0), at(frac(1, 2), frac(1, 2))}), grid(1),
                        frac(1, 10));
    CHECK_FALSE(g.local(0).length.exact());
    CHECK(g.q(0) == 8);
  }
}

TEST_CASE("a circle on 2x2: four quarter arcs", "[mc][curve]") {
  // Centre (1,1), radius 1/2: π/4 in every region; ⌈(π/4)/(1/10)⌉ = ⌈7.85⌉ = 8. The
  // natural start (3/2,1) lies on y = 1 and is where the circle enters region 3.
  const CurveOnGrid g(Curve::circle(at(1, 1), frac(1, 2)), grid(2), frac(1, 10));
  CHECK(g.q() == std::vector<std::int64_t>{8, 8, 8, 8});
  CHECK(g.in().size() == 4);
  Real total = 0;
  for (RegionId u = 0; u < 4; ++u) {
    CHECK(close(g.local(u).length.value(), pi / 4));
    total += g.local(u).length.value();
  }
  CHECK(close(total, pi));
  CHECK(close(g.point(0), to_point(at(frac(3, 2), 1))));
  // Clockwise on the screen: 3, 2, 0, 1. (1, 3/2) belongs to region 3 and (1, 1/2) to 1.
  CHECK(close(g.local(3).inf, 0));
  CHECK(g.local(3).inf_owned);
  CHECK(g.local(3).sup_owned);
  CHECK(close(g.local(2).inf, pi / 4));
  CHECK_FALSE(g.local(2).inf_owned);
  CHECK(close(g.local(0).inf, pi / 2));
  CHECK(close(g.local(1).inf, 3 * pi / 4));
  CHECK(g.local(1).inf_owned);
  CHECK_FALSE(g.local(1).sup_owned);
  CHECK(close(g.point(pi / 8), {1 + sqrt(Real(2)) / 4, 1 + sqrt(Real(2)) / 4}));
}

TEST_CASE("a circle through a grid vertex: the vertex is one point of region 3", "[mc][curve]") {
  // Centre (7/10, 3/5), radius 1/2 passes (1,1) = centre + (3/10, 2/5), and also (1, 1/5)
  // and (2/5, 1), which are antipodal: region 0 holds exactly half the circle.
  const CurveOnGrid g(Curve::circle(at(frac(7, 10), frac(3, 5)), frac(1, 2)), grid(2), frac(1, 10));
  CHECK(g.q() == std::vector<std::int64_t>{16, 10, 7, 0}); // ⌈5π⌉, ⌈9.27⌉, ⌈6.44⌉
  CHECK(g.in() == std::vector<RegionId>{0, 1, 2});
  const LocalPart& vertex = g.local(3);
  CHECK_FALSE(vertex.empty);
  CHECK(vertex.length.zero());
  CHECK(close(g.point(vertex.inf), to_point(at(1, 1))));
  CHECK(close(g.local(0).length.value(), pi / 2)); // half of 2π·(1/2)
  const Real spanned = 2 * atan(Real(4) / 3);      // the angle region 1 spans
  CHECK(close(g.local(1).length.value(), spanned / 2));
}

TEST_CASE("too close to a multiple of σ to decide: PrecisionError, not a guess", "[mc][curve]") {
  // A circle of radius 1/4 inside one region has length π/2. With σ = π/2 cut after 95
  // digits, |A_u|/σ is within 10^-94 of 1; cut after 30 digits, it is clearly above 1.
  const std::string digits = "15707963267948966192313216916397514420985846996875529104874722961"
                             "5390820314310449931401741267105853399107404325664115332";
  auto truncated = [&](std::size_t n) {
    return Rational(boost::multiprecision::cpp_int(digits.substr(0, n)),
                    boost::multiprecision::pow(boost::multiprecision::cpp_int(10),
                                               static_cast<unsigned>(n - 1)));
  };
  const Curve circle = Curve::circle(at(frac(1, 2), frac(1, 2)), frac(1, 4));
  CHECK_THROWS_AS(CurveOnGrid(circle, grid(1), truncated(95)), PrecisionError);
  CHECK_THROWS_WITH(CurveOnGrid(circle, grid(1), truncated(95)),
                    Catch::Contains("region 0 (row 0, col 0)"));
  CHECK(CurveOnGrid(circle, grid(1), truncated(30)).q(0) == 2);
  CHECK(CurveOnGrid(circle, grid(1), frac(1, 4)).q(0) == 7); // ⌈2π⌉
}

TEST_CASE("Γ_u(p), Γ_u⁻¹(x) and the nearest point on a polyline", "[mc][curve]") {
  const CurveOnGrid g(Curve::polyline({at(frac(1, 2), frac(1, 2)), at(frac(5, 2), frac(1, 2)),
                                       at(frac(5, 2), frac(5, 2))}),
                      grid(3), frac(1, 2));
  CHECK(close(g.point(1, Real(1)), real_point(1.5, 0.5)));
  CHECK(close(g.point(2, Real(2)), real_point(2.5, 0.5)));
  // The closure: Γ_2(sup P_2) = (5/2, 1) belongs to region 5 but is still Γ_2's end.
  CHECK(close(g.point(2, Real("2.5")), real_point(2.5, 1)));
  CHECK_THROWS_AS(g.point(2, Real(3)), std::out_of_range);
  CHECK_THROWS_AS(g.point(4, Real(0)), std::invalid_argument);

  const auto on = g.parameter(1, real_point(1.25, 0.5));
  REQUIRE(on);
  CHECK(close(*on, Real("0.75")));
  CHECK_FALSE(g.parameter(1, real_point(1.25, 0.6)));
  for (const char* p : {"1.5", "1.9", "2", "2.25", "2.5"}) {
    const auto back = g.parameter(2, g.point(2, Real(p)));
    REQUIRE(back);
    CHECK(close(*back, Real(p)));
  }

  SECTION("nearest: the foot of the perpendicular, or an end of Γ_u") {
    const NearestPoint n = g.nearest(2, to_point(at(frac(23, 10), frac(9, 10))));
    CHECK(close(n.parameter, Real("2.4")));
    CHECK(close(n.point, to_point(at(frac(5, 2), frac(9, 10)))));
    CHECK(close(n.distance, Real("0.2")));
    const NearestPoint end = g.nearest(1, real_point(0.2, 0.2));
    CHECK(close(end.parameter, Real("0.5")));
    CHECK(close(end.point, real_point(1, 0.5)));
  }
  SECTION("nearest: equally near points, the smallest parameter") {
    // (2.2, 0.8) is 0.3 from (2.2, 0.5) at p = 1.7 and from (2.5, 0.8) at p = 2.3.
    const NearestPoint n = g.nearest(2, to_point(at(frac(11, 5), frac(4, 5))));
    CHECK(close(n.parameter, Real("1.7")));
  }
}

TEST_CASE("Γ_u⁻¹ and the nearest point on a circle", "[mc][curve]") {
  const CurveOnGrid g(Curve::circle(at(1, 1), frac(1, 2)), grid(2), frac(1, 10));
  // Region 3 holds the quarter from (3/2,1) to (1,3/2), parameters [0, π/4].
  const NearestPoint diagonal = g.nearest(3, real_point(2, 2));
  CHECK(close(diagonal.parameter, pi / 8));
  CHECK(close(diagonal.point, {1 + sqrt(Real(2)) / 4, 1 + sqrt(Real(2)) / 4}));
  // The centre is equally near every point: the smallest parameter of Γ_3.
  const NearestPoint centre = g.nearest(3, real_point(1, 1));
  CHECK(close(centre.parameter, 0));
  // Beyond the arc's end: the nearer end.
  CHECK(close(g.nearest(3, real_point(1.9, 0.9)).parameter, 0));
  CHECK(close(g.nearest(0, real_point(1.9, 0.9)).parameter, 3 * pi / 4));
  for (const Real& p : {pi / 2, pi / 2 + Real("0.1"), 3 * pi / 4}) {
    const auto back = g.parameter(0, g.point(0, p));
    REQUIRE(back);
    CHECK(close(*back, p));
  }
  // Region 1 ends where Γ closes: its sup is the whole length.
  const auto end = g.parameter(1, g.point(1, pi));
  REQUIRE(end);
  CHECK(close(*end, pi));
}

TEST_CASE("curves that are not simple or leave the square are rejected", "[mc][curve]") {
  CHECK_THROWS_WITH(Curve::polyline({at(0, 0), at(1, 1), at(1, 0), at(0, 1)}, true),
                    Catch::Contains("not simple"));
  CHECK_THROWS_WITH(Curve::polyline({at(0, 0), at(1, 0), at(frac(1, 2), 0)}),
                    Catch::Contains("fold back"));
  CHECK_THROWS_WITH(Curve::polyline({at(0, 0), at(0, 0), at(1, 0)}), Catch::Contains("length 0"));
  CHECK_THROWS_AS(Curve::polyline({at(0, 0)}), std::invalid_argument);
  CHECK_THROWS_AS(Curve::circle(at(1, 1), 0), std::invalid_argument);
  CHECK_THROWS_WITH(Curve({Circle{at(1, 1), frac(1, 2)}, Circle{at(frac(3, 2), 1), frac(1, 2)}}),
                    Catch::Contains("components 0 and 1 meet"));
  CHECK_THROWS_WITH(Curve({Circle{at(1, 1), frac(1, 2)}, Polyline{{at(0, 0), at(2, 2)}, false}}),
                    Catch::Contains("every one closed"));
  CHECK_THROWS_WITH(CurveOnGrid(Curve::circle(at(1, 1), frac(3, 2)), grid(2), frac(1, 4)),
                    Catch::Contains("leaves the deployment square"));
  CHECK_THROWS_AS(CurveOnGrid(Curve::circle(at(1, 1), frac(1, 2)), grid(2), 0),
                  std::invalid_argument);
}

TEST_CASE("simulation curves C1, C2, C3 on m = 10 (seed 002 §VII)", "[mc][curve]") {
  const GridTiling tiling = grid(10);
  const CurveOnGrid c1(curve_c1(10), tiling, frac(1, 4));
  CHECK(c1.in() == std::vector<RegionId>{66, 67, 68, 69, 76, 79, 86, 89, 96, 97, 98, 99});
  CHECK(c1.q_min() == 4);
  CHECK(c1.q_max() == 4);
  const CurveOnGrid c2(curve_c2(10), tiling, frac(1, 4));
  CHECK(c2.in() == std::vector<RegionId>{0, 1, 2, 3, 10, 13, 20, 23, 30, 31, 32, 33});
  const CurveOnGrid c3(curve_c3(10), tiling, frac(1, 4));
  CHECK(c3.in() == std::vector<RegionId>{23, 24, 25, 26, 32, 33, 34, 35, 36, 37, 42,
                                         43, 44, 45, 46, 47, 52, 53, 54, 55, 56, 57,
                                         62, 63, 64, 65, 66, 67, 73, 74, 75, 76});
  CHECK(c3.format_q() == ". . . . . . . . . .\n"
                         ". . . . . . . . . .\n"
                         ". . . 3 5 5 3 . . .\n"
                         ". . 3 3 4 4 3 3 . .\n"
                         ". . 5 4 2 2 4 5 . .\n"
                         ". . 5 4 2 2 4 5 . .\n"
                         ". . 3 3 4 4 3 3 . .\n"
                         ". . . 3 5 5 3 . . .\n"
                         ". . . . . . . . . .\n"
                         ". . . . . . . . . .\n");
  Real total = 0;
  for (RegionId u = 0; u < tiling.size(); ++u)
    total += c3.local(u).length.value();
  CHECK(close(total, 2 * pi * Real(frac(15, 4)), Real("1e-90"))); // radii 5/4 and 5/2
  // Γ runs over the inner circle on [0, 2π·5/4), then the outer one.
  const Point middle = to_point(at(5, 5));
  CHECK(close(c3.offset(1), 2 * pi * Real(frac(5, 4))));
  CHECK(close(distance(c3.point(Real("0.3")), middle), Real("1.25")));
  CHECK(close(distance(c3.point(c3.offset(1) + Real("0.3")), middle), Real("2.5")));
  CHECK(simulation_curve("c3", 10).name() == "C3");
  CHECK_THROWS_WITH(simulation_curve("C4", 10), Catch::Contains("choose C1, C2 or C3"));
}

TEST_CASE("simulation curves are valid for the paper's m = 10..20", "[mc][curve]") {
  for (int m = 10; m <= 20; ++m)
    for (const char* name : {"C1", "C2", "C3"}) {
      INFO(name << " m=" << m);
      const CurveOnGrid g(simulation_curve(name, m), grid(m), frac(1, 4));
      CHECK(g.q_min() >= 1);
      if (std::string(name) != "C3") // a ⌊m/3⌋×⌊m/3⌋ ring of regions, b in each
        CHECK(g.in().size() == static_cast<std::size_t>(4 * (m / 3)));
    }
  // C3's default radii m/8 and m/4 are too close on some small grids: a region meets both.
  CHECK_THROWS_WITH(CurveOnGrid(curve_c3(4), grid(4), frac(1, 4)),
                    Catch::Contains("curve C3 meets region 10 (row 2, col 2) with components"));
}

TEST_CASE("seeded random curves: the local parts partition Γ", "[mc][curve]") {
  // Random polylines and circles with small rational coordinates on 1×1 … 5×5 grids (those
  // that are not simple, leave the square or enter a region twice are skipped). For each:
  // Σ|A_u| = |Γ|; every sampled Γ(p) off the grid lines lies in the region whose P_u
  // holds p; Γ_u⁻¹(Γ_u(p)) = p.
  std::mt19937 rng(20240607);
  int checked = 0;
  for (int iteration = 0; iteration < 400; ++iteration) {
    const int m = 1 + static_cast<int>(rng() % 5);
    const int den = 1 + static_cast<int>(rng() % 6);
    auto coordinate = [&] { return Rational(static_cast<int>(rng() % (m * den + 1)), den); };
    const bool circle = rng() % 2 == 0;
    std::optional<CurveOnGrid> g;
    try {
      if (circle) {
        const Rational radius(1 + static_cast<int>(rng() % (m * den)), 2 * den);
        const RationalPoint centre{coordinate(), coordinate()};
        g.emplace(Curve::circle(centre, radius), grid(m), Rational(1, 1 + rng() % 7));
      } else {
        std::vector<RationalPoint> vertices;
        const int n = 2 + static_cast<int>(rng() % 5);
        for (int i = 0; i < n; ++i)
          vertices.push_back({coordinate(), coordinate()});
        const bool closed = n >= 3 && rng() % 2 == 0;
        g.emplace(Curve::polyline(vertices, closed), grid(m), Rational(1, 1 + rng() % 7));
      }
    } catch (const std::invalid_argument&) {
      continue;
    }
    ++checked;
    INFO("iteration " << iteration);
    Real total = 0;
    for (RegionId u = 0; u < g->size(); ++u)
      total += g->local(u).length.value();
    CHECK(close(total, g->length(), Real("1e-80")));
    auto on_line = [](const Real& v) { return abs(v - floor(v + Real("0.5"))) < Real("1e-50"); };
    for (int k = 0; k < 40; ++k) {
      const Real p = g->length() * (Real(k) + Real("0.37")) / 40;
      const Point x = g->point(p);
      if (on_line(x.x) || on_line(x.y))
        continue;
      const RegionId u = g->region_of(x);
      const LocalPart& part = g->local(u);
      REQUIRE_FALSE(part.empty);
      CHECK(p >= part.inf);
      CHECK(p <= part.sup);
      const auto back = g->parameter(u, x, Real("1e-40"));
      REQUIRE(back);
      CHECK(close(*back, p, Real("1e-40")));
    }
  }
  CHECK(checked > 100);
}
