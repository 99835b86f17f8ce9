// The machinery of the one-step lemma checks (proofs/round_lemma.hpp): symmetry reduction,
// determinism, the random search and the shrinker.
#include <catch2/catch.hpp>

#include "proofs/lemma_6_1.hpp"
#include "proofs/lemma_6_4.hpp"

using namespace proofs;

namespace {

Family tiny(mc::Neighbourhood nbh) {
  Family f;
  f.sides = {{2, 4}, {3, 1}};
  f.neighbourhoods = {nbh};
  f.ks = {1, 2};
  f.rho2s = {{9, 10}, {1, 10}};
  return f;
}

} // namespace

TEST_CASE("round lemmas: the symmetry reduction gives the same verdicts and figures as none",
          "[proofs][engine]") {
  for (auto nbh : {mc::Neighbourhood::four, mc::Neighbourhood::eight})
    for (const RoundLemma* lemma : {&lemma_6_1(), &lemma_6_4()}) {
      Family reduced = tiny(nbh), plain = tiny(nbh);
      plain.use_symmetry = false;
      const LemmaCheck a = check_family(*lemma, reduced);
      const LemmaCheck b = check_family(*lemma, plain);
      INFO(lemma->name << ", neighbourhood " << to_string(nbh));
      CHECK(a.instances < b.instances);
      CHECK(b.skipped == 0);
      CHECK(a.represented == b.instances);
      CHECK(a.instances + a.skipped == b.instances);
      CHECK(a.outcomes_represented == b.outcomes);
      CHECK(a.result.verdict == b.result.verdict);
      REQUIRE(a.claims.size() == b.claims.size());
      for (std::size_t i = 0; i < a.claims.size(); ++i) {
        INFO(a.claims[i].claim.id);
        CHECK(a.claims[i].verdict() == b.claims[i].verdict());
        CHECK(a.claims[i].premise_represented == b.claims[i].premise);
        CHECK(a.claims[i].violations_represented == b.claims[i].violations);
        CHECK(a.claims[i].undecided == 0);
        // The smallest counterexample has the same size (it may be another image).
        CHECK(a.claims[i].smallest.has_value() == b.claims[i].smallest.has_value());
        if (a.claims[i].smallest && b.claims[i].smallest)
          CHECK(a.claims[i].smallest->robots() == b.claims[i].smallest->robots());
      }
    }
}

TEST_CASE("round lemmas: the same results for 1 and 2 threads and on every run",
          "[proofs][engine]") {
  const Family f = tiny(mc::Neighbourhood::eight);
  CheckOptions one, two;
  two.threads = 2;
  const LemmaCheck a = check_lemma_6_4(f, one);
  const LemmaCheck b = check_lemma_6_4(f, two);
  const LemmaCheck c = check_lemma_6_4(f, one);
  CHECK(b.result.threads == 2);
  for (const LemmaCheck* other : {&b, &c}) {
    CHECK(a.result.verdict == other->result.verdict);
    CHECK(a.result.message == other->result.message);
    CHECK(a.result.figures == other->result.figures);
    CHECK(a.result.notes == other->result.notes);
  }
}

TEST_CASE("round lemmas: the random search is reproducible from its seed", "[proofs][engine]") {
  SearchOptions options;
  options.samples = 300;
  options.neighbourhood = mc::Neighbourhood::eight;
  const LemmaCheck a = search_lemma_6_4(options);
  const LemmaCheck b = search_lemma_6_4(options);
  CHECK(a.result.verdict == b.result.verdict);
  CHECK(a.result.message == b.result.message);
  CHECK(a.result.figures == b.result.figures);
  CHECK(a.result.notes == b.result.notes);
  options.seed = 2;
  const LemmaCheck other = search_lemma_6_4(options);
  CHECK(other.result.figures != a.result.figures);
  CHECK_THAT(a.result.figures.front().second,
             Catch::Contains("random search, seed 1, 300 samples"));
}

TEST_CASE("round lemmas: beyond the outcome limit the search samples outcomes, reproducibly",
          "[proofs][engine]") {
  SearchOptions options;
  options.samples = 1000;
  options.outcome_limit = 1; // every instance with a choice of order is sampled
  options.sampled_outcomes = 8;
  const LemmaCheck a = search_lemma_6_1(options);
  const LemmaCheck b = search_lemma_6_1(options);
  CHECK(a.sampled_outcome_instances > 0);
  CHECK(a.sampled_outcome_instances == b.sampled_outcome_instances);
  CHECK(a.outcomes == b.outcomes);
  CHECK(a.result.message.rfind("holds on 1000 samples", 0) == 0);
}

TEST_CASE("round lemmas: the shrinker reduces a large counterexample", "[proofs][engine]") {
  // 5×5, the curve along the middle row, hundreds of robots: boundary regions next to the
  // curve pour robots into it, which breaks the conference's Lemma 2(2).
  Setting s;
  s.m = 5;
  s.neighbourhood = mc::Neighbourhood::four;
  s.curve = "line";
  s.q = curve_q("line", 5);
  s.k = 3;
  s.rho2 = {9, 10};
  Counts counts(25);
  for (std::size_t u = 0; u < counts.size(); ++u)
    counts[u] = static_cast<RobotCount>(100 + 37 * u % 400);
  const std::size_t claim = 2; // L2(2)
  REQUIRE(lemma_6_4().claims[claim].id == "L2(2)");
  const auto found = find_violation(lemma_6_4(), claim, Instance{s, counts});
  REQUIRE(found);
  CHECK(found->robots() > 5000);
  const RoundCounterexample small = shrink(lemma_6_4(), claim, *found);
  CHECK(small.robots() <= 6);
  CHECK(small.setting.m == 2);
  CHECK(small.setting.k == 1);
  CHECK(small.setting.curve == "shrunk from line");
  // Still a counterexample, and shrinking again changes nothing.
  CHECK(find_violation(lemma_6_4(), claim, Instance{small.setting, small.before}));
  const RoundCounterexample again = shrink(lemma_6_4(), claim, small);
  CHECK(again.before == small.before);
  CHECK(again.setting.q == small.setting.q);
}

TEST_CASE("round lemmas: the counterexample prints as the instance, both rounds and the flow",
          "[proofs][engine]") {
  Setting s;
  s.m = 2;
  s.neighbourhood = mc::Neighbourhood::four;
  s.curve = "line";
  s.q = curve_q("line", 2);
  s.k = 1;
  s.rho2 = {1, 2};
  const auto found = find_violation(lemma_6_4(), 2, Instance{s, {0, 2, 2, 1}});
  REQUIRE(found);
  CHECK(found->lines() ==
        std::vector<std::string>{
            "counterexample to L2(2): m = 2, neighbourhood 4, curve line, k = 1, rho2 = 1/2; 5 "
            "robots",
            "  q (units of sigma; . = off the curve):",
            "    . .",
            "    1 1",
            "  counts at t:",
            "    0 2",
            "    2 1",
            "  flow of round t (from->to: robots; (row,col), row 0 at the top):",
            "    (0,1)->(1,1): 1",
            "  counts at t+1:",
            "    0 1",
            "    2 2",
            "  fails: g = (1,1), h = (1,0): y_g(t)/q_g = 1 < y_h(t)/q_h = 2 = max over Nbrs_g, but "
            "y_g(t+1)/q_g = 2 > y_h/q_h - sigma/q_max^2 = 1 (q_max = 1 sigma; g receives 1 from "
            "(0,1) and sends nothing)",
            "  as a round configuration (tioa-check round --config, -p config=): "
            "{\"m\":2,\"nbh\":4,\"k\":1,\"rho1\":\"1/2\",\"rho2\":\"1/2\",\"q\":[[0,0],[1,1]],"
            "\"robots\":[[0,2],[2,1]]}",
        });
}

TEST_CASE("round lemmas: SplitMix64 is the reference generator", "[proofs][engine]") {
  SplitMix64 random(0);
  CHECK(random.next() == 0xe220a8397b1dcdafULL);
  SplitMix64 dice(7);
  for (int i = 0; i < 1000; ++i)
    CHECK(dice.below(6) < 6);
  CHECK_THROWS_AS(dice.below(0), std::invalid_argument);
}
