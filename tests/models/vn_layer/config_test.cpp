// The round-length rules of the conference layer (seed 002 §V-B, line 162) and the lattice's
// own (models/vn_layer/README.md), and the instances that cannot be built.
#include <catch2/catch.hpp>

#include "models/vn_layer/config.hpp"

TEST_CASE("vn-layer round rules: the paper's 11.05 and the lattice's 12 on 2x1", "[vn-layer]") {
  vn_layer::VnConfig c; // d_MMT = d_v = ε = d_r = 1, b = v_c = 2: 9 + max(1.58, 2.05)
  CHECK(c.paper_round_bound_text() == "11.05");
  CHECK(vn_layer::lattice_round_bound(c) == 12); // 9 + ⌈3/2⌉ + 1
  c.delta = 12;
  CHECK(vn_layer::paper_round_rule_holds(c));
  c.delta = 11;
  CHECK_FALSE(vn_layer::paper_round_rule_holds(c));
  c.rows = 1; // no neighbour: the farthest target is in the zone, b = 2 away
  CHECK(vn_layer::lattice_round_bound(c) == 11);
}

TEST_CASE("vn-layer round rules: the restart term decides when d_r is large", "[vn-layer]") {
  vn_layer::VnConfig c;
  c.d_r = 3; // 9 + √10·2/6 + 3 = 13.05
  c.delta = 13;
  CHECK_FALSE(vn_layer::paper_round_rule_holds(c));
  c.delta = 14;
  CHECK(vn_layer::paper_round_rule_holds(c));
}

TEST_CASE("vn-layer invalid: the target-trigger must fall inside the round", "[vn-layer]") {
  vn_layer::VnConfig c;
  CHECK_FALSE(vn_layer::invalid(c));
  c.delta = 6; // d_MMT + 3d_v + 2ε = 6
  REQUIRE(vn_layer::invalid(c));
  CHECK_THAT(*vn_layer::invalid(c), Catch::Contains("target-trigger phase"));
  c.delta = 13;
  c.cns = 4;
  CHECK(vn_layer::invalid(c));
}
