// Lemma 6.5 / conference Lemma 3 (proofs/lemma_6_5.hpp) and the fixed-point check
// (proofs/fixpoint_lemma.hpp) it shares with Lemmas 6.6 and 6.7: pinned figures on a small family
// for both neighbourhoods, the same figures for every thread count, and a deliberately too-small
// bound caught.
#include <catch2/catch.hpp>

#include "proofs/lemma_6_5.hpp"
#include "tests/proofs/small_family.hpp"

using namespace proofs;
using proofs::testing::small_family;


TEST_CASE("lemma 6.5: T_out beside the journal's bound on a small family, both neighbourhoods",
          "[proofs][lemma-6.5]") {
  struct Row {
    mc::Neighbourhood nbh;
    std::uint64_t rounds;
  };
  for (const Row& row :
       {Row{mc::Neighbourhood::four, 6'363}, Row{mc::Neighbourhood::eight, 4'864}}) {
    INFO("neighbourhood " << to_string(row.nbh));
    const FixpointCheck check = check_lemma_6_5(small_family(row.nbh));
    CHECK(check.result.name == "lemma-6.5");
    CHECK(check.result.kind == "round-lemma");
    CHECK(check.result.verdict == checker::Verdict::holds);
    CHECK(check.instances == 15'104);
    CHECK(check.skipped == 23'328);
    CHECK(check.rounds == row.rounds);
    CHECK(check.result.states == check.instances);
    CHECK(check.result.edges == check.rounds);
    CHECK(!check.counterexample);
    const BoundTally& t_out = check.claim("6.5");
    CHECK(t_out.premise == check.instances);
    CHECK(t_out.violations == 0);
    REQUIRE(t_out.largest);
    // The worst T_out is 1 round: 2×2, the curve on one region, 2 robots; the bound
    // (1 + ρ3)m²n²(2m² + 1) + m²n with ρ3 = 1/(1 − 1/2) = 2, m = 2, n = 2 is 3·16·9 + 8 = 440.
    CHECK(t_out.largest->measurement.value == 1);
    CHECK(t_out.largest->measurement.bound == 440);
    CHECK(t_out.largest->robots() == 2);
    CHECK(t_out.largest->setting.curve == "point");
    CHECK(check.claim("6.5 window").violations == 0);
    CHECK(check.result.figures.front().first == "covered");
    CHECK_THAT(check.result.figures.front().second,
               Catch::Contains("15104 instances run to the fixed point in the default order"));
  }
}

TEST_CASE("lemma 6.5: the same figures for every thread count", "[proofs][lemma-6.5]") {
  const FixpointCheck one = check_lemma_6_5(small_family(mc::Neighbourhood::eight), {.threads = 1});
  const FixpointCheck two = check_lemma_6_5(small_family(mc::Neighbourhood::eight), {.threads = 2});
  CHECK(one.result.figures == two.result.figures);
  CHECK(one.result.notes == two.result.notes);
}

TEST_CASE("lemma 6.5: a too-small bound (T_out = t0) is violated, with the smallest "
          "counterexample",
          "[proofs][lemma-6.5]") {
  FixpointLemma wrong = lemma_6_5();
  wrong.name = "lemma-6.5-wrong";
  const auto evaluate = wrong.evaluate;
  wrong.evaluate = [evaluate](const FixpointInstance& instance,
                              std::vector<std::optional<Measurement>>& out) {
    evaluate(instance, out);
    out[0]->bound = 0; // "the Out sets never change": false
  };
  const FixpointCheck check = check_fixpoint_family(wrong, small_family(mc::Neighbourhood::four));
  CHECK(check.result.verdict == checker::Verdict::violated);
  REQUIRE(check.counterexample);
  CHECK(check.counterexample->claim == "6.5");
  CHECK(check.counterexample->robots() == 2);
  CHECK(check.counterexample->setting.m == 2);
  CHECK(check.counterexample->measurement.value == 1);
  CHECK(check.claim("6.5").violations > 0);
  CHECK_THAT(check.result.message, Catch::Contains("smallest counterexample: 2 robots, m = 2"));
  // The counterexample is printed round by round in the notes.
  bool printed = false;
  for (const std::string& note : check.result.notes)
    printed = printed || note.find("measured 1 > bound 0") != std::string::npos;
  CHECK(printed);
}

TEST_CASE("lemma 6.5: the symmetry reduction leaves the worst T_out unchanged on a small family",
          "[proofs][lemma-6.5]") {
  // The default order is not symmetric (see fixpoint_lemma.hpp), so this is measured, not implied.
  for (auto nbh : {mc::Neighbourhood::four, mc::Neighbourhood::eight}) {
    INFO("neighbourhood " << to_string(nbh));
    Family reduced = small_family(nbh), full = small_family(nbh);
    full.use_symmetry = false;
    const FixpointCheck a = check_lemma_6_5(reduced), b = check_lemma_6_5(full);
    CHECK(b.instances == a.instances + a.skipped);
    CHECK(b.skipped == 0);
    CHECK(a.claim("6.5").largest->measurement.value == b.claim("6.5").largest->measurement.value);
    CHECK(b.claim("6.5").violations == 0);
  }
}
