// The measures of Theorem 1 at a round start (proofs/vn_layer/assignment_measures.hpp), on
// hand-made counts and points.

#include <catch2/catch.hpp>

#include "proofs/vn_layer/assignment_measures.hpp"

namespace {

vn_layer::VnConfig config(int rows, int cols, int b) {
  vn_layer::VnConfig c;
  c.rows = rows;
  c.cols = cols;
  c.b = b;
  return c;
}

} // namespace

TEST_CASE("density_spread: the densest minus the sparsest zone of In", "[vn-layer]") {
  // q = (4, 2, 0): zone 2 is off the curve, and a zone with no CN is not in In.
  const std::vector<mc::QuantisedLength> q{4, 2, 0};
  CHECK(vn_layer::density_spread({3, 1, 5}, q) == mc::Rational(1, 4)); // 3/4 − 1/2
  CHECK(vn_layer::density_spread({1, 2, 0}, q) == mc::Rational(3, 4)); // 1 − 1/4
  CHECK(vn_layer::density_spread({0, 2, 9}, q) == 0);                  // In = {1}
  CHECK(vn_layer::density_spread({0, 0, 9}, q) == 0);                  // In = ∅
}

TEST_CASE("proportionality_bound: 10(2m-1)/(q_min rho2), m = max(rows, cols)", "[vn-layer]") {
  CHECK(vn_layer::proportionality_bound(config(2, 1, 2)) == mc::Rational(50, 3)); // 30/(2·9/10)
  CHECK(vn_layer::proportionality_bound(config(1, 1, 4)) == mc::Rational(25, 9)); // 10/(4·9/10)
  vn_layer::VnConfig c = config(1, 3, 2);
  c.rho2 = mc::Rational(1, 2);
  CHECK(vn_layer::proportionality_bound(c) == 50); // 10·5/(2·1/2)
}

TEST_CASE("spacing_gap: the distance of each zone's CNs to even spacing", "[vn-layer]") {
  // 1×2 of side 4: x in [0, 8], the curve at y = 2; zone 0 owns x < 4.
  const vn_layer::VnConfig c = config(1, 2, 4);
  const vn_layer::Lattice lattice = c.lattice();
  const auto at = [&](int x) { return lattice.point(x, 2); };
  SECTION("evenly spaced, or fewer than two CNs in a zone") {
    CHECK(vn_layer::spacing_gap(c, lattice, {at(0), at(2)}).distance == 2); // ends 0 and 4
    CHECK(vn_layer::spacing_gap(c, lattice, {at(4), at(8)}).distance == 0);
    CHECK(vn_layer::spacing_gap(c, lattice, {at(0), -1, at(5)}).distance == 0);
    CHECK(vn_layer::spacing_gap(c, lattice, {}).where.empty());
  }
  SECTION("the worst zone is named, with its CNs' x and the even ones") {
    const vn_layer::SpacingGap gap =
        vn_layer::spacing_gap(c, lattice, {at(4), at(7), at(5), at(8), at(0), at(1)});
    // Zone 0: x = 0, 1 against 0, 4: 3. Zone 1: 4, 5, 7, 8 against 4, 16/3, 20/3, 8: 1/3.
    CHECK(gap.distance == 3);
    CHECK(gap.where == "zone 0: CNs at x = 0, 1, evenly spaced at x = 0, 4");
  }
  SECTION("with owned_ends, P_h of a zone not in the last column ends one unit short") {
    vn_layer::VnConfig owned = c;
    owned.owned_ends = true;
    CHECK(vn_layer::spacing_gap(owned, lattice, {at(0), at(3)}).distance == 0);
    CHECK(vn_layer::spacing_gap(c, lattice, {at(0), at(3)}).distance == 1);
  }
}
