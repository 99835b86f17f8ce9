// assign of seed 002 Fig. 7 on counts (models/mc/assign.hpp): every branch of the figure
// on hand-computed instances, the cap n − e, exact floors and comparisons, and the order
// in which lower is processed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "models/mc/assign.hpp"

using namespace mc;

namespace {

const Rational nine_tenths{9, 10};

AssignResult assign_in(const GridTiling& grid, RegionId h, const std::vector<RobotCount>& y,
                       const std::vector<QuantisedLength>& q, RobotCount k) {
  return assign(vn_view(grid, h, y, q), AssignParams(k, nine_tenths));
}

// The neighbours h sends robots to, as {id, robots}, in id order.
std::vector<std::pair<RegionId, RobotCount>> sends(const VnView& view, const AssignResult& r) {
  std::vector<std::pair<RegionId, RobotCount>> out;
  for (std::size_t i = 0; i < view.neighbours.size(); ++i)
    if (r.sent[i] != 0)
      out.emplace_back(view.neighbours[i].id, r.sent[i]);
  return out;
}

using Sends = std::vector<std::pair<RegionId, RobotCount>>;

VnView make_view(RobotCount y, QuantisedLength q, std::vector<NeighbourView> neighbours) {
  VnView view;
  view.h = 0;
  view.y = y;
  view.q = q;
  view.neighbours = std::move(neighbours);
  return view;
}

} // namespace

TEST_CASE("assign: y(h) <= e reassigns nothing (line 6)", "[mc][assign]") {
  const GridTiling grid(3, Neighbourhood::eight);
  std::vector<RobotCount> y(9, 0);
  std::vector<QuantisedLength> q(9, 0);
  y[4] = 3;
  q[1] = 2;
  const AssignResult r = assign_in(grid, 4, y, q, 3);
  CHECK(r.branch == AssignBranch::keep);
  CHECK(r.lower.empty());
  CHECK(r.total_sent() == 0);
  CHECK(assign_in(grid, 4, y, q, 2).total_sent() == 1); // y(h) = 3 > e = 2: boundary, In = {1}
}

TEST_CASE("assign: on the curve, lower and the floors of lines 7-12", "[mc][assign]") {
  // 3×3, 4-neighbourhood, h = 4 (the centre) with nbrs 1 (north), 3 (west), 5 (east),
  // 7 (south). q_h = 2, y(h) = 30, e = 1, ρ2 = 9/10.
  //   1: q = 1, y = 5   (q_g/q_h)·y(h) = 15 > 5    → lower
  //   3: q = 4, y = 70                    60 ≤ 70  → not lower
  //   5: q = 2, y = 10                    30 > 10  → lower
  //   7: q = 0, y = 0   off the curve: not in In, never in lower although it is empty
  // |lower| = 2: ra_1 = ⌊0.9·(15 − 5)/6⌋ = ⌊1.5⌋ = 1, ra_5 = ⌊0.9·(30 − 10)/6⌋ = 3.
  const GridTiling grid(3, Neighbourhood::four);
  const std::vector<QuantisedLength> q{0, 1, 0, 4, 2, 2, 0, 0, 0};
  const std::vector<RobotCount> y{0, 5, 0, 70, 30, 10, 0, 0, 0};
  const VnView view = vn_view(grid, 4, y, q);
  const AssignResult r = assign(view, AssignParams(1, nine_tenths));
  CHECK(r.branch == AssignBranch::on_curve);
  CHECK(r.lower == std::vector<RegionId>{1, 5});
  CHECK(r.ideal == std::vector<RobotCount>{1, 0, 3, 0});
  CHECK(sends(view, r) == Sends{{1, 1}, {5, 3}});
  CHECK(r.total_sent() == 4);
}

TEST_CASE("assign: a neighbour without robots has y(g) = 0 and can receive", "[mc][assign]") {
  // Its VN is failed (no robot emulates it), so VN_h resets V(g) to <0, 0> (Fig. 6
  // lines 48-50); g stays in In and in lower. 2×2, 4-neighbourhood, h = 0 with nbrs 1, 2.
  const GridTiling grid(2, Neighbourhood::four);
  const std::vector<QuantisedLength> q{1, 1, 1, 1};
  const std::vector<RobotCount> y{20, 0, 0, 0};
  const VnView view = vn_view(grid, 0, y, q);
  const AssignResult r = assign(view, AssignParams(1, nine_tenths));
  // |lower| = 2: ⌊0.9·20/6⌋ = 3 to each.
  CHECK(r.lower == std::vector<RegionId>{1, 2});
  CHECK(sends(view, r) == Sends{{1, 3}, {2, 3}});
}

TEST_CASE("assign: off the curve with no curve neighbour (lines 13-18)", "[mc][assign]") {
  // 3×3, 8-neighbourhood, no curve at all; h = 0 (a corner) with nbrs 1, 3, 4.
  //   1: y = 10 < 50 → lower;  3: y = 50, not fewer → not lower;  4: y = 0 → lower
  // |lower| = 2: ra_1 = ⌊0.9·40/6⌋ = 6, ra_4 = ⌊0.9·50/6⌋ = ⌊7.5⌋ = 7.
  const GridTiling grid(3, Neighbourhood::eight);
  const std::vector<QuantisedLength> q(9, 0);
  std::vector<RobotCount> y(9, 0);
  y[0] = 50;
  y[1] = 10;
  y[3] = 50;
  const VnView view = vn_view(grid, 0, y, q);
  const AssignResult r = assign(view, AssignParams(1, nine_tenths));
  CHECK(r.branch == AssignBranch::no_curve_neighbour);
  CHECK(r.lower == std::vector<RegionId>{1, 4});
  CHECK(sends(view, r) == Sends{{1, 6}, {4, 7}});
}

TEST_CASE("assign: on the boundary, line 20 splits y(h) - e equally over In", "[mc][assign]") {
  // 3×3, 8-neighbourhood, h = 4 off the curve; In = {2, 5, 8}. ra = ⌊(y(h) − e)/|In|⌋ to
  // each g ∈ In whatever its count (5 has 100 robots), nothing to the others (0 has none).
  const GridTiling grid(3, Neighbourhood::eight);
  std::vector<QuantisedLength> q(9, 0);
  q[2] = 1;
  q[5] = 3;
  q[8] = 1;
  std::vector<RobotCount> y(9, 0);
  y[4] = 12;
  y[5] = 100;
  const VnView view = vn_view(grid, 4, y, q);
  AssignResult r = assign(view, AssignParams(1, nine_tenths));
  CHECK(r.branch == AssignBranch::boundary);
  CHECK(r.lower == std::vector<RegionId>{2, 5, 8});
  CHECK(sends(view, r) == Sends{{2, 3}, {5, 3}, {8, 3}}); // ⌊11/3⌋ = 3; 3 robots stay
  r = assign(view, AssignParams(4, nine_tenths));
  CHECK(sends(view, r) == Sends{{2, 2}, {5, 2}, {8, 2}}); // ⌊8/3⌋ = 2; 6 robots stay
  CHECK(assign_every_order(view, AssignParams(4, nine_tenths)).size() == 1);
}

TEST_CASE("assign: the cap n - e leaves e robots (lines 10 and 16)", "[mc][assign]") {
  SECTION("on the curve: both ideals exceed what is left") {
    // q_h = 1, y(h) = 10, e = 3; two empty neighbours with q = 10: ideal
    // ⌊0.9·(10·10 − 0)/6⌋ = 15 each, but only n − e = 7 can go: all to the first.
    const VnView view = make_view(10, 1, {{1, 0, 10}, {2, 0, 10}});
    const AssignResult r = assign(view, AssignParams(3, nine_tenths));
    CHECK(r.ideal == std::vector<RobotCount>{15, 15});
    CHECK(r.sent == std::vector<RobotCount>{7, 0});
    CHECK(view.y - r.total_sent() == 3);
  }
  SECTION("off the curve (line 16)") {
    // y(h) = 7, e = 6, two empty neighbours: ideal ⌊0.9·7/6⌋ = 1 each, n − e = 1.
    const VnView view = make_view(7, 0, {{1, 0, 0}, {2, 0, 0}});
    const AssignResult r = assign(view, AssignParams(6, nine_tenths));
    CHECK(r.ideal == std::vector<RobotCount>{1, 1});
    CHECK(r.sent == std::vector<RobotCount>{1, 0});
  }
}

TEST_CASE("assign: floors and comparisons are exact", "[mc][assign]") {
  SECTION("line 10: the floor of an exact integer") {
    // 2×2, 4-neighbourhood, h = 0 (q = 3, y = 25), nbrs 1 (q = 4) and 2 (q = 3), both empty.
    // ra_1 = ⌊0.9·((4/3)·25 − 0)/6⌋ = ⌊5⌋ = 5; in floating point the same expression is
    // 4.999… and floors to 4.
    const GridTiling grid(2, Neighbourhood::four);
    const VnView view = vn_view(grid, 0, std::vector<RobotCount>{25, 0, 0, 0},
                                std::vector<QuantisedLength>{3, 4, 3, 0});
    const AssignResult r = assign(view, AssignParams(1, nine_tenths));
    CHECK(r.sent == std::vector<RobotCount>{5, 3}); // ⌊0.9·25/6⌋ = ⌊3.75⌋ = 3 to region 2
    const double rho2 = 0.9, qg = 4, qh = 3, yh = 25, yg = 0;
    CHECK(std::floor(rho2 * (qg / qh * yh - yg) / (2 * (2 + 1))) == 4); // what doubles say
  }
  SECTION("line 8: a neighbour exactly at the normalised count is not in lower") {
    // q_h = 3, y(h) = 27; region 1: q = 7, y = 63 = (7/3)·27 exactly (in floating point
    // (7/3)·27 > 63). So lower = {2} and ra_2 = ⌊0.9·27/4⌋ = ⌊6.075⌋ = 6; with region 1
    // wrongly in lower it would be ⌊0.9·27/6⌋ = 4.
    const GridTiling grid(2, Neighbourhood::four);
    const VnView view = vn_view(grid, 0, std::vector<RobotCount>{27, 63, 0, 0},
                                std::vector<QuantisedLength>{3, 7, 3, 0});
    const AssignResult r = assign(view, AssignParams(1, nine_tenths));
    CHECK(r.lower == std::vector<RegionId>{2});
    CHECK(r.sent == std::vector<RobotCount>{0, 6});
    const double qg = 7, qh = 3, yh = 27, yg = 63;
    CHECK(qg / qh * yh > yg); // what doubles say
  }
  SECTION("a ρ2 beyond 64 bits takes the arbitrary-precision path") {
    // ρ2 = (10^30 − 1)/10^30: ⌊ρ2·20/6⌋ = ⌊3.333…⌋ = 3, as with ρ2 = 9/10 → 3.
    const Rational rho2 = *support::parse_rational("999999999999999999999999999999/"
                                                   "1000000000000000000000000000000");
    const AssignParams params(1, rho2);
    CHECK_FALSE(params.small());
    const VnView view = make_view(20, 1, {{1, 0, 1}, {2, 0, 1}});
    CHECK(assign(view, params).sent == std::vector<RobotCount>{3, 3});
    // ⌊ρ2·(2·20)/(1·6)⌋ = ⌊6.666…⌋ = 6 with q_g = 2.
    CHECK(assign(make_view(20, 1, {{1, 0, 2}, {2, 0, 1}}), params).sent ==
          std::vector<RobotCount>{6, 3});
  }
}

TEST_CASE("assign: the order of lower matters once the cap binds", "[mc][assign]") {
  // q_h = 1, y(h) = 10, e = 3 (n − e = 7); |lower| = 2, divisor 1·2·3 = 6:
  //   region 1: q = 4, y = 10 → ideal ⌊0.9·(40 − 10)/6⌋ = ⌊4.5⌋ = 4
  //   region 2: q = 5, y = 10 → ideal ⌊0.9·(50 − 10)/6⌋ = 6
  // Order (1, 2): 4, then min(6, 3) = 3.  Order (2, 1): 6, then min(4, 1) = 1.
  const VnView view = make_view(10, 1, {{1, 10, 4}, {2, 10, 5}});
  const AssignParams params(3, nine_tenths);
  const AssignResult by_id = assign(view, params);
  CHECK(by_id.lower == std::vector<RegionId>{1, 2});
  CHECK(by_id.ideal == std::vector<RobotCount>{4, 6});
  CHECK(by_id.sent == std::vector<RobotCount>{4, 3});
  const std::vector<RegionId> reversed{2, 1};
  const AssignResult other = assign(view, params, reversed);
  CHECK(other.lower == reversed);
  CHECK(other.sent == std::vector<RobotCount>{1, 6});

  const std::vector<AssignResult> every = assign_every_order(view, params);
  REQUIRE(every.size() == 2);
  CHECK(every[0].sent == std::vector<RobotCount>{1, 6}); // sorted by `sent`
  CHECK(every[0].lower == reversed);
  CHECK(every[1].sent == std::vector<RobotCount>{4, 3});

  const std::vector<RegionId> not_lower{1, 3};
  CHECK_THROWS_AS(assign(view, params, not_lower), std::invalid_argument);
  const std::vector<RegionId> too_short{1};
  CHECK_THROWS_AS(assign(view, params, too_short), std::invalid_argument);
}

TEST_CASE("assign: assign_every_order is every permutation of lower, deduplicated",
          "[mc][assign]") {
  // Against brute force: run assign in every permutation of lower (up to 8! orders) and
  // collect the distinct outcomes.
  std::mt19937_64 random(20240611);
  auto pick = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(random);
  };
  const std::vector<Rational> rhos{{9, 10}, {1, 2}, {1, 3}, {99, 100}};
  std::size_t order_dependent = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const bool on_curve = trial % 2 == 0;
    std::vector<NeighbourView> neighbours;
    const int count = static_cast<int>(pick(1, 8));
    for (int i = 0; i < count; ++i)
      neighbours.push_back({static_cast<RegionId>(i + 1), pick(0, 12), on_curve ? pick(0, 6) : 0});
    const VnView view = make_view(pick(0, 40), on_curve ? pick(1, 3) : 0, neighbours);
    const AssignParams params(pick(1, 8), rhos[static_cast<std::size_t>(trial) % rhos.size()]);

    const AssignResult by_id = assign(view, params);
    std::set<std::vector<RobotCount>> brute;
    std::vector<RegionId> order = by_id.lower;
    if (by_id.branch == AssignBranch::on_curve ||
        by_id.branch == AssignBranch::no_curve_neighbour) {
      std::sort(order.begin(), order.end());
      do
        brute.insert(assign(view, params, order).sent);
      while (std::next_permutation(order.begin(), order.end()));
    } else {
      brute.insert(by_id.sent);
    }
    std::set<std::vector<RobotCount>> every;
    for (const AssignResult& r : assign_every_order(view, params)) {
      every.insert(r.sent);
      CHECK(assign(view, params, r.lower).sent == r.sent); // its order reproduces it
      CHECK(r.total_sent() <= std::max<RobotCount>(0, view.y - params.k()));
    }
    CHECK(every == brute);
    CHECK(every.count(by_id.sent) == 1);
    order_dependent += every.size() > 1;
  }
  CHECK(order_dependent > 10); // the family reaches the cap
}

TEST_CASE("assign: bad input throws", "[mc][assign]") {
  CHECK_THROWS_AS(AssignParams(0, Rational(1, 2)), std::invalid_argument);
  CHECK_THROWS_AS(AssignParams(1, Rational(0)), std::invalid_argument);
  CHECK_THROWS_AS(AssignParams(1, Rational(1)), std::invalid_argument);
  const GridTiling grid(2, Neighbourhood::four);
  CHECK_THROWS_AS(
      vn_view(grid, 0, std::vector<RobotCount>{1, 2, 3}, std::vector<QuantisedLength>{0, 0, 0, 0}),
      std::invalid_argument);
  CHECK_THROWS_AS(vn_view(grid, 0, std::vector<RobotCount>{1, -2, 3, 4},
                          std::vector<QuantisedLength>{0, 0, 0, 0}),
                  std::invalid_argument);
  CHECK_THROWS_AS(vn_view(grid, 4, std::vector<RobotCount>{1, 2, 3, 4},
                          std::vector<QuantisedLength>{0, 0, 0, 0}),
                  std::invalid_argument);
}
