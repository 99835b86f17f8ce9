// Lemma 6.4 / conference Lemma 2 (proofs/lemma_6_4.hpp): what holds and what does not, with
// the smallest counterexamples pinned.
#include <catch2/catch.hpp>

#include "proofs/lemma_6_4.hpp"
#include "tests/proofs/small_family.hpp"

using namespace proofs;
using proofs::testing::small_round_family;

namespace {

Instance instance(int m, mc::Neighbourhood nbh, std::vector<QuantisedLength> q, Counts counts,
                  RobotCount k = 1, mc::Rational rho2 = {9, 10}) {
  Setting s;
  s.m = m;
  s.neighbourhood = nbh;
  s.curve = "hand-made";
  s.q = std::move(q);
  s.k = k;
  s.rho2 = std::move(rho2);
  return {s, std::move(counts)};
}

std::size_t index_of(const std::string& id) {
  const auto& claims = lemma_6_4().claims;
  for (std::size_t i = 0; i < claims.size(); ++i)
    if (claims[i].id == id)
      return i;
  FAIL("no claim " << id);
  return 0;
}

} // namespace

TEST_CASE("lemma 6.4, 4-neighbourhood: (1) and the journal's (2) hold; the conference's (2) "
          "fails where a boundary region sends",
          "[proofs][lemma-6.4]") {
  const LemmaCheck check = check_lemma_6_4(small_round_family(mc::Neighbourhood::four));
  CHECK(check.result.verdict == checker::Verdict::violated);
  CHECK(check.instances == 162'488); // as for Lemma 6.1: the same family
  CHECK(check.outcomes == 162'530);
  CHECK(check.claim("L2(1)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("6.4(1)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("6.4(2)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("L2(2)").verdict() == checker::Verdict::violated);
  CHECK(check.claim("L2(1) step").verdict() == checker::Verdict::holds);
  CHECK(check.claim("L2(2) sigma step (as stated)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("L2(2) sigma step (as used)").verdict() == checker::Verdict::holds);
  for (const ClaimTally& c : check.claims)
    CHECK(c.premise > 0);
  REQUIRE(check.counterexample);
  const RoundCounterexample& cx = *check.counterexample;
  CHECK(cx.claim == "L2(2)");
  CHECK(cx.robots() == 5);
  CHECK(cx.setting.m == 2);
  CHECK(cx.setting.q == std::vector<QuantisedLength>{0, 0, 1, 1});
  CHECK(cx.before == Counts{0, 2, 2, 1});
  CHECK(cx.after == Counts{0, 1, 2, 2});
  CHECK(cx.flow.transfers == std::vector<mc::Transfer>{{1, 3, 1}});
  CHECK_THAT(cx.why, Catch::Contains("g receives 1 from (0,1)"));
  // The boundary region's transfer puts the round outside the journal's window.
  const mc::RoundSystem system = cx.setting.system();
  const RoundStep step{system, cx.before, cx.flow, cx.after};
  const auto outside = journal_window(step);
  REQUIRE(outside);
  CHECK_THAT(*outside, Catch::Contains("Lemma 6.3"));
}

TEST_CASE("lemma 6.4, 8-neighbourhood: the journal's (2) fails when five neighbours send",
          "[proofs][lemma-6.4]") {
  const LemmaCheck check = check_lemma_6_4(small_round_family(mc::Neighbourhood::eight));
  CHECK(check.result.verdict == checker::Verdict::violated);
  CHECK(check.claim("6.4(2)").verdict() == checker::Verdict::violated);
  CHECK(check.claim("L2(2)").verdict() == checker::Verdict::violated);
  // Counts up to 2 on 3×3 are too few for part (1) to fail (see the next test).
  CHECK(check.claim("L2(1)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("6.4(1)").verdict() == checker::Verdict::holds);
  const auto& journal = check.claim("6.4(2)");
  REQUIRE(journal.smallest);
  CHECK(journal.smallest->robots() == 15);
  CHECK(journal.smallest->setting.curve == "hub-3");
  CHECK(journal.smallest->before == Counts{0, 2, 2, 2, 1, 2, 2, 2, 2});
  CHECK(journal.smallest->after[4] == 6); // 6/3 = 2 > 2 − (1/10)/9
}

TEST_CASE("lemma 6.4, 8-neighbourhood: part (1) fails from a plateau of 6 around one robot",
          "[proofs][lemma-6.4]") {
  // The smallest the shrinker finds (and the fewest robots possible on 3×3: each sender must
  // have lower = {g} and y_f − y_g >= 5, and five senders are needed): 43 robots.
  const Counts counts{0, 6, 6, 6, 1, 6, 6, 6, 6};
  const auto eight = instance(3, mc::Neighbourhood::eight, curve_q("none", 3), counts);
  for (const char* id : {"L2(1)", "6.4(1)", "L2(1) step"}) {
    const auto found = find_violation(lemma_6_4(), index_of(id), eight);
    REQUIRE(found);
    CHECK(found->after[4] == 6);
  }
  const auto four = instance(3, mc::Neighbourhood::four, curve_q("none", 3), counts);
  for (const char* id : {"L2(1)", "6.4(1)", "L2(1) step"})
    CHECK(!find_violation(lemma_6_4(), index_of(id), four));
}

TEST_CASE("lemma 6.4: the sigma/q_max^2 step is decided exactly", "[proofs][lemma-6.4]") {
  // q = 1 and 3, q_max = 3: densities 1/3 and 2/3 differ by exactly 1/3 >= 1/9; 4/9 would
  // not be a density here. The 4-neighbourhood line-1-3 family exercises the step.
  Family f = small_round_family(mc::Neighbourhood::four);
  f.curves = {"line-1-3", "checker-1-3", "hub-3"};
  const LemmaCheck check = check_lemma_6_4(f);
  CHECK(check.claim("L2(2) sigma step (as stated)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("L2(2) sigma step (as used)").verdict() == checker::Verdict::holds);
  CHECK(check.claim("L2(2) sigma step (as stated)").premise > 1000);
  // Equality is allowed: on 2×2 with q = 1 everywhere and k = 2 nobody sends; g = (0,0) with
  // 1 robot, h = (0,1) with 2: y_g(t+1)/q_g = 1 = y_h/q_h − sigma/q_max^2 exactly.
  const auto exact = instance(2, mc::Neighbourhood::four, {1, 1, 1, 1}, {1, 2, 1, 1}, 2);
  CHECK(!find_violation(lemma_6_4(), index_of("L2(2)"), exact));
}
