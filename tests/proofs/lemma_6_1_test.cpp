// Lemma 6.1 / conference Lemma 1 (proofs/lemma_6_1.hpp): holds on a small family for both
// neighbourhoods, on a random search, and a deliberately false strengthening is caught.
#include <catch2/catch.hpp>

#include "proofs/lemma_6_1.hpp"
#include "tests/proofs/small_family.hpp"

using namespace proofs;
using proofs::testing::small_round_family;

TEST_CASE("lemma 6.1: every part holds on a small family, both neighbourhoods",
          "[proofs][lemma-6.1]") {
  // 3 + 8 + 9 curves × 2 k × 2 rho2 on 1×1 (counts 0..3), 2×2 (0..4) and 3×3 (0..2): 728 636
  // configurations, 162 488 up to symmetry; an instance has more than one outcome when a
  // cap n − k binds with several neighbours in lower.
  struct Row {
    mc::Neighbourhood nbh;
    std::uint64_t instances, skipped, outcomes;
  };
  for (const Row& row : {Row{mc::Neighbourhood::four, 162'488, 566'148, 162'530},
                         Row{mc::Neighbourhood::eight, 162'488, 566'148, 162'515}}) {
    const LemmaCheck check = check_lemma_6_1(small_round_family(row.nbh));
    INFO("neighbourhood " << to_string(row.nbh));
    CHECK(check.result.name == "lemma-6.1");
    CHECK(check.result.kind == "round-lemma");
    CHECK(check.result.verdict == checker::Verdict::holds);
    CHECK(check.instances == row.instances);
    CHECK(check.skipped == row.skipped);
    CHECK(check.outcomes == row.outcomes);
    CHECK(check.result.states == check.instances);
    CHECK(check.result.edges == check.outcomes);
    CHECK(!check.counterexample);
    for (const ClaimTally& c : check.claims) {
      CHECK(c.verdict() == checker::Verdict::holds);
      CHECK(c.premise > 0); // no part holds vacuously
    }
    CHECK(check.result.figures.front().first == "covered");
    CHECK_THAT(check.result.figures.front().second,
               Catch::Contains(std::to_string(check.instances) + " instances checked"));
  }
}

TEST_CASE("lemma 6.1: a false strengthening is violated, with the smallest counterexample",
          "[proofs][lemma-6.1]") {
  // "(1) with k + 1": a region with at least k robots keeps k + 1. False: a region with k + 1
  // robots on the boundary sends one to its only curve neighbour.
  RoundLemma wrong = lemma_6_1();
  wrong.name = "lemma-6.1-wrong";
  wrong.claims = {{"wrong(1)", "if y(u,t) >= k then y(u,t+1) >= k + 1", "a deliberate error"}};
  wrong.evaluate = [](const RoundStep& step, std::vector<ClaimOutcome>& out) {
    const RobotCount k = step.system.params().k;
    for (RegionId u = 0; u < step.before.size(); ++u)
      if (step.before[u] >= k) {
        ++out[0].premise;
        if (step.after[u] < k + 1 && !out[0].failure)
          out[0].failure = "region " + region_name(step.system.grid().m(), u) + " keeps " +
                           std::to_string(step.after[u]);
      }
  };
  Family f = small_round_family(mc::Neighbourhood::four);
  const LemmaCheck check = check_family(wrong, f);
  CHECK(check.result.verdict == checker::Verdict::violated);
  REQUIRE(check.counterexample);
  // The smallest: one robot on a 1×1 grid with k = 1 keeps 1 < 2.
  CHECK(check.counterexample->robots() == 1);
  CHECK(check.counterexample->setting.m == 1);
  CHECK(check.counterexample->before == Counts{1});
  CHECK(check.result.message.rfind("violated: wrong(1)", 0) == 0);
  REQUIRE(check.result.notes.size() >= 2);
  CHECK_THAT(check.result.notes[check.result.notes.size() - 2],
             Catch::Contains("fails: region (0,0) keeps 1"));
  CHECK_THAT(check.result.notes.back(),
             Catch::EndsWith("config=): {\"m\":1,\"nbh\":4,\"k\":1,\"rho1\":\"1/2\","
                             "\"rho2\":\"1/2\",\"q\":[[0]],\"robots\":[[1]]}"));
}

TEST_CASE("lemma 6.1: the random search reports 'holds on N samples', never 'holds'",
          "[proofs][lemma-6.1]") {
  SearchOptions options;
  options.samples = 500;
  options.neighbourhood = mc::Neighbourhood::eight;
  const LemmaCheck check = search_lemma_6_1(options);
  CHECK(check.result.verdict == checker::Verdict::incomplete);
  CHECK(check.result.message.rfind("holds on 500 samples", 0) == 0);
  CHECK(check.instances == 500);
  for (const ClaimTally& c : check.claims)
    CHECK(c.verdict() == checker::Verdict::holds);
}
