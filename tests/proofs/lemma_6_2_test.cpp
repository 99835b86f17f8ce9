// Lemmas 6.2 and 6.3 (proofs/lemma_6_2.hpp, lemma_6_3.hpp): t1 and t2 measured by hand on one
// run, pinned figures on a small family for both neighbourhoods, and a too-small bound caught.
#include <catch2/catch.hpp>

#include "proofs/lemma_6_3.hpp"
#include "tests/proofs/small_family.hpp"

using namespace proofs;
using proofs::testing::small_family;

namespace {

// 1×3 is not a square grid; use 2×2 with the top row on the curve (q = 1, 1) and every robot
// in the bottom-right region, which is off the curve.
struct OneRun {
  Setting setting;
  mc::RoundSystem system;
  Counts start;
  mc::FixpointRun run;
  FixpointInstance instance;

  explicit OneRun(Counts counts)
      : setting(make_setting()), system(setting.system()), start(std::move(counts)),
        run(system.run_to_fixpoint(start)), instance{setting, system, start, run, rho3(system)} {}

  static Setting make_setting() {
    Setting s;
    s.m = 2;
    s.neighbourhood = mc::Neighbourhood::four;
    s.curve = "top row";
    s.q = {1, 1, 0, 0};
    s.k = 1;
    s.rho2 = {1, 2};
    return s;
  }
};

} // namespace

TEST_CASE("lemmas 6.2 and 6.3: t1 and t2 on one run, by hand", "[proofs][lemma-6.2][lemma-6.3]") {
  // 9 robots in (1,1), off the curve. Round 0: (1,1) is a boundary region (its neighbour
  // (0,1) is on the curve) and sends ⌊(9 − 1)/1⌋ = 8 robots to (0,1): In grows from {} to
  // {(0,1)}. Later rounds spread the robots along the top row and never off it again.
  OneRun one({0, 0, 0, 9});
  const mc::FixpointRun& run = one.run;
  REQUIRE(run.fixpoint_round >= 2);
  CHECK(run.rounds[1] == Counts{0, 8, 0, 1});
  CHECK_FALSE(same_in_out(run.rounds[0], run.rounds[1]));
  CHECK(out_feeds_in(one.instance, 0) == false); // (0,1) had no robots: not in In(0)
  for (std::size_t t = 0; t < run.fixpoint_round; ++t)
    CHECK(keeps_sets(one.instance, t));
  // In changes in round 0 (from {} to {(0,1)}) and in round 1 ((0,0) gets robots).
  const std::size_t t1 = measured_t1(one.instance);
  CHECK(t1 == 2);
  CHECK(measured_t2(one.instance, t1) == 2);
  CHECK(one.instance.rho3 == 2); // 1²/(1 − 1/2)

  std::vector<std::optional<Measurement>> out(2);
  lemma_6_2().evaluate(one.instance, out);
  REQUIRE(out[0]);
  CHECK(out[0]->value == 2);
  CHECK(out[0]->bound == 2 * 4 * 3 * 4 * 81); // 2m²·(1 + ρ3)m²n², m = 2, n = 9
  REQUIRE(out[1]);
  CHECK(out[1]->value == 2);
  CHECK(out[1]->bound == 8);
}

TEST_CASE("lemma 6.3: a boundary region that feeds an active curve region delays t2",
          "[proofs][lemma-6.3]") {
  // 1 robot in (0,1) on the curve, 9 in (1,1) below it: round 0 sends 8 of them to (0,1),
  // which is in In(0), so t2 >= 1.
  OneRun one({0, 1, 0, 9});
  CHECK(out_feeds_in(one.instance, 0));
  const std::size_t t1 = measured_t1(one.instance);
  CHECK(measured_t2(one.instance, t1) >= 1);
  CHECK(measured_t2(one.instance, t1) >= t1);
}

TEST_CASE("lemmas 6.2 and 6.3 hold on a small family, far inside their bounds",
          "[proofs][lemma-6.2][lemma-6.3]") {
  struct Row {
    mc::Neighbourhood nbh;
    std::int64_t largest_t1, largest_t2;
  };
  for (const Row& row : {Row{mc::Neighbourhood::four, 2, 1}, Row{mc::Neighbourhood::eight, 1, 1}}) {
    INFO("neighbourhood " << to_string(row.nbh));
    const FixpointCheck l62 = check_lemma_6_2(small_family(row.nbh));
    CHECK(l62.result.name == "lemma-6.2");
    CHECK(l62.result.verdict == checker::Verdict::holds);
    REQUIRE(l62.claim("6.2").largest);
    CHECK(l62.claim("6.2").largest->measurement.value == row.largest_t1);
    CHECK(l62.claim("6.2 step").violations == 0);
    const FixpointCheck l63 = check_lemma_6_3(small_family(row.nbh));
    CHECK(l63.result.verdict == checker::Verdict::holds);
    REQUIRE(l63.claim("6.3").largest);
    CHECK(l63.claim("6.3").largest->measurement.value == row.largest_t2);
    CHECK(l63.claim("6.3 from t0").violations == 0);
    CHECK(l62.instances == l63.instances);
  }
}

TEST_CASE("lemma 6.2: a bound of zero rounds is violated with a small counterexample",
          "[proofs][lemma-6.2]") {
  FixpointLemma wrong = lemma_6_2();
  wrong.name = "lemma-6.2-wrong";
  const auto evaluate = wrong.evaluate;
  wrong.evaluate = [evaluate](const FixpointInstance& instance,
                              std::vector<std::optional<Measurement>>& out) {
    evaluate(instance, out);
    if (out[0])
      out[0]->bound = 0;
  };
  const FixpointCheck check = check_fixpoint_family(wrong, small_family(mc::Neighbourhood::four));
  CHECK(check.result.verdict == checker::Verdict::violated);
  REQUIRE(check.counterexample);
  CHECK(check.counterexample->claim == "6.2");
  CHECK(check.counterexample->measurement.value >= 1);
}
