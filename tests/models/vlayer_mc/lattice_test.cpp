// The lattice and the constants of VLayer[MC] (models/vlayer_mc/lattice.hpp, config.hpp).
#include <catch2/catch.hpp>

#include "models/vlayer_mc/config.hpp"

using vlayer_mc::Lattice;

TEST_CASE("vlayer lattice: points, ownership, centres, neighbours", "[vlayer]") {
  const Lattice one_by_two(1, 2, 2, mc::Neighbourhood::four);
  CHECK(one_by_two.points() == 15); // 5 × 3
  CHECK(one_by_two.region_of(one_by_two.point(1, 1)) == 0);
  CHECK(one_by_two.region_of(one_by_two.point(2, 1)) == 1); // an interior line: east owns it
  CHECK(one_by_two.region_of(one_by_two.point(4, 2)) == 1); // the far sides: the last region
  CHECK(one_by_two.centre(0) == one_by_two.point(1, 1));
  CHECK(one_by_two.centre(1) == one_by_two.point(3, 1));
  CHECK(one_by_two.nbrs(0) == std::vector<int>{1});
  CHECK(one_by_two.r() == 4);

  const Lattice four(2, 2, 2, mc::Neighbourhood::four), eight(2, 2, 2, mc::Neighbourhood::eight);
  CHECK(four.nbrs(0) == std::vector<int>{1, 2});
  CHECK(eight.nbrs(0) == std::vector<int>{1, 2, 3});
  CHECK_FALSE(four.in_nbrs_plus(0, 3));
  CHECK(eight.in_nbrs_plus(0, 3));
  CHECK(four.region_of(four.point(2, 2)) == 3); // a vertex: the south-east region

  CHECK(Lattice(1, 1, 2, mc::Neighbourhood::four).r() == 2); // no neighbours: b
  CHECK_THROWS_AS(Lattice(1, 2, 3, mc::Neighbourhood::four), std::invalid_argument);
}

TEST_CASE("vlayer lattice: one quantum of motion at vmax (D8)", "[vlayer]") {
  const Lattice l(1, 2, 2, mc::Neighbourhood::four);
  CHECK(l.step_toward(l.point(0, 0), l.point(4, 2), 1) == l.point(1, 1));
  CHECK(l.step_toward(l.point(0, 0), l.point(4, 2), 3) == l.point(3, 2));
  CHECK(l.step_toward(l.point(3, 2), l.point(4, 2), 3) == l.point(4, 2)); // stops on it
  CHECK(l.distance(l.point(0, 0), l.point(4, 2)) == 4);
}

TEST_CASE("vlayer config: the round-length rule of seed 000 §5.5", "[vlayer]") {
  vlayer_mc::VlConfig c; // e 0, d 1, eps 0, r 4, vmax 4, d_r 1
  CHECK(vlayer_mc::round_length_bound(c) == 5);
  CHECK(vlayer_mc::round_length_ok(c)); // delta 6
  c.delta = 5;
  CHECK_FALSE(vlayer_mc::round_length_ok(c));
  CHECK_FALSE(vlayer_mc::invalid(c)); // breaking the rule is allowed: it is a question to ask
  vlayer_mc::VlConfig paper;
  paper.e = 1;
  paper.eps = 1;
  paper.delta = 11;
  paper.eps_sample = 2;
  paper.vmax = 2;
  CHECK(vlayer_mc::round_length_bound(paper) == 10);
  CHECK(vlayer_mc::round_length_ok(paper));
  paper.delta = 4; // target phase e + 2d + 2eps = 5 is outside the round
  CHECK(vlayer_mc::invalid(paper));
}
