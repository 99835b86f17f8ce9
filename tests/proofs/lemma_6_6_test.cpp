// Lemma 6.6 / conference Lemmas 4 and 5 (proofs/lemma_6_6.hpp): pinned figures on a small
// family for both neighbourhoods, and a deliberately too-small bound caught.
#include <catch2/catch.hpp>

#include "proofs/lemma_6_6.hpp"
#include "tests/proofs/small_family.hpp"

using namespace proofs;
using proofs::testing::small_family;


TEST_CASE("lemma 6.6: T_stab and |C_out| beside their bounds on a small family",
          "[proofs][lemma-6.6]") {
  struct Row {
    mc::Neighbourhood nbh;
    std::int64_t stab_window, stab_window_bound, step;
    std::uint64_t step_premise;
  };
  for (const Row& row : {Row{mc::Neighbourhood::four, 2, 320, 3, 9'092},
                         Row{mc::Neighbourhood::eight, 2, 288, 4, 9'212}}) {
    INFO("neighbourhood " << to_string(row.nbh));
    const FixpointCheck check = check_lemma_6_6(small_family(row.nbh));
    CHECK(check.result.name == "lemma-6.6");
    CHECK(check.result.verdict == checker::Verdict::holds);
    CHECK(check.instances == 15'104);
    const BoundTally& window = check.claim("6.6");
    REQUIRE(window.largest);
    CHECK(window.largest->measurement.value == row.stab_window);
    CHECK(window.largest->measurement.bound == row.stab_window_bound);
    CHECK(check.claim("6.6 total").violations == 0);
    CHECK(check.claim("6.6 total").largest->measurement.value == 3);
    // With a curve, |C_out| at T_out is at most 8 (far below the bound, ≥ 270 on 2×2).
    const BoundTally& c_out = check.claim("L5");
    CHECK(c_out.violations == 0);
    CHECK(c_out.largest->measurement.value == 8);
    CHECK(c_out.largest->measurement.bound >= 270);
    // Without a curve nothing moves off Out: 16 robots on 2×2 against
    // (k+4)(2m−1)m + 10m²(2m−1)/ρ2 = 5·3·2 + 120/(1/2) = 270 (reported, not deciding).
    const BoundTally& no_curve = check.claim("L5 no curve");
    CHECK(!no_curve.claim.decides_verdict);
    CHECK(no_curve.largest->measurement.value == 16);
    CHECK(no_curve.largest->measurement.bound == 270);
    const BoundTally& step = check.claim("L5 step");
    CHECK(!step.claim.decides_verdict);
    CHECK(step.premise == row.step_premise);
    CHECK(step.largest->measurement.value == row.step);
  }
}

TEST_CASE("lemma 6.6: a too-small bound on |C_out| (at most k) is violated",
          "[proofs][lemma-6.6]") {
  FixpointLemma wrong = lemma_6_6();
  wrong.name = "lemma-6.6-wrong";
  const auto evaluate = wrong.evaluate;
  wrong.evaluate = [evaluate](const FixpointInstance& instance,
                              std::vector<std::optional<Measurement>>& out) {
    evaluate(instance, out);
    if (out[2])
      out[2]->bound = instance.system.params().k; // "L5" with bound k
  };
  const FixpointCheck check = check_fixpoint_family(wrong, small_family(mc::Neighbourhood::eight));
  CHECK(check.result.verdict == checker::Verdict::violated);
  REQUIRE(check.counterexample);
  CHECK(check.counterexample->claim == "L5");
  CHECK(check.counterexample->robots() == 2);
  CHECK(check.counterexample->setting.m == 2);
  CHECK(check.claim("6.6").violations == 0);
}
