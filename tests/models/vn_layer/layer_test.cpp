// The composed conference layer on 2×1 with both CNs at the bottom-left corner (zone 1, off
// the curve): the boundary branch of assign (seed 001 Fig. 4 lines 19–22) sends one CN to
// the centre of zone 0, whose VN starts failed and is restarted within d_r.
#include <catch2/catch.hpp>

#include "checker/checks.hpp"
#include "models/vn_layer/layer.hpp"
#include "tioa/operators.hpp"

namespace vn_layer_test {

using vn_layer::VnConfig;

tioa::Automaton from_corner(const VnConfig& c) {
  const tioa::Automaton layer = vn_layer::vn_layer(c);
  const vn_layer::Lattice lattice = c.lattice();
  const std::vector<vn_layer::Point> corner(static_cast<std::size_t>(c.cns),
                                            lattice.point(0, lattice.height() - 1));
  return tioa::Start(layer, vn_layer::placed_start(layer, c, corner));
}

} // namespace vn_layer_test

using vn_layer::VnConfig;
using vn_layer_test::from_corner;

TEST_CASE("vn-layer 2x1: one CN reaches o_0 in round 1 and VN_0 comes alive", "[vn-layer]") {
  const VnConfig c;
  const tioa::Automaton system = from_corner(c);
  const auto x0 = tioa::find_variable<int>(system, "CN_0.x");
  const auto x1 = tioa::find_variable<int>(system, "CN_1.x");
  const auto vn0_failed = tioa::find_variable<bool>(system, "VN_0.failed");
  const int o0 = c.lattice().centre(0);
  const auto reached =
      checker::check_invariant(system, [=](const tioa::State& s) { return s[x0] != o0; }, {});
  REQUIRE(reached.verdict == checker::Verdict::violated);
  REQUIRE(reached.trace);
  // Round 1 is [13, 26): the target-trigger at 13 + 6, delivered, answered and delivered
  // again in no time at the earliest, then 2 quanta of travel.
  CHECK(reached.trace->steps.back().time == 21);
  // Nobody ever stands at o_0 with VN_0 still failed once d_r has passed: at o_0 it can
  // wait, but never into the next round (round-timing covers that); here: CN_1 stays put.
  const auto stays =
      checker::check_invariant(system, [=](const tioa::State& s) { return s[x1] != o0; }, {});
  CHECK(stays.verdict == checker::Verdict::holds);
  const auto restarted = checker::check_invariant(
      system, [=](const tioa::State& s) { return !(s[x0] == o0 && !s[vn0_failed]); }, {});
  CHECK(restarted.verdict == checker::Verdict::violated);
}

TEST_CASE("vn-layer: the VNs start alive with vn_start=alive, and never fail with "
          "vn_fail=never",
          "[vn-layer]") {
  VnConfig c;
  c.vns_start_failed = false;
  c.vn_fail = vn_layer::VnFail::never;
  const tioa::Automaton system = from_corner(c);
  const auto vn0_failed = tioa::find_variable<bool>(system, "VN_0.failed");
  const auto vn1_failed = tioa::find_variable<bool>(system, "VN_1.failed");
  const auto r = checker::check_invariant(
      system, [=](const tioa::State& s) { return !s[vn0_failed] && !s[vn1_failed]; }, {});
  CHECK(r.verdict == checker::Verdict::holds);
}
