// The seeded random search of the fixed-point lemmas (proofs/fixpoint_search.hpp): never a
// plain "holds", reproducible from its seed for every thread count, and a violation shrunk
// to a small counterexample.
#include <catch2/catch.hpp>

#include "proofs/fixpoint_search.hpp"
#include "proofs/lemma_6_5.hpp"
#include "proofs/lemma_6_7.hpp"

using namespace proofs;

namespace {

// A synthetic claim that fails whenever the grid holds 3 robots or more.
FixpointLemma at_most_two_robots() {
  FixpointLemma lemma;
  lemma.name = "at-most-two";
  lemma.description = "a false claim: at most 2 robots";
  lemma.claims = {{"two", "n <= 2", "a test"}};
  lemma.evaluate = [](const FixpointInstance& instance,
                      std::vector<std::optional<Measurement>>& out) {
    out[0] = Measurement{mc::total(instance.start), 2, "n robots"};
  };
  return lemma;
}

FixpointSearchOptions few_samples(mc::Neighbourhood nbh) {
  FixpointSearchOptions options;
  options.samples = 30;
  options.neighbourhood = nbh;
  options.max_side = 3;
  return options;
}

} // namespace

TEST_CASE("fixpoint search: a lemma that holds on every sample is 'holds on N samples', "
          "never 'holds'",
          "[proofs][fixpoint-search]") {
  const FixpointCheck check = search_fixpoint(lemma_6_5(), few_samples(mc::Neighbourhood::four));
  CHECK(check.result.name == "lemma-6.5");
  CHECK(check.result.kind == "round-lemma");
  CHECK(check.result.verdict == checker::Verdict::incomplete);
  CHECK(check.result.message.rfind("holds on 30 samples (a random search, not a proof); ", 0) == 0);
  CHECK(check.instances == 30);
  CHECK(check.result.states == 30);
  CHECK(check.rounds > 0);
  CHECK(check.result.edges == check.rounds);
  CHECK(!check.counterexample);
  CHECK(check.claim("6.5").premise == 30);
  CHECK(check.claim("6.5").violations == 0);
  REQUIRE(check.result.figures.front().first == "covered");
  CHECK_THAT(check.result.figures.front().second,
             Catch::StartsWith("random search, seed 1, 30 samples: m in 2..3, neighbourhood 4"));
  // Hundreds of robots per region.
  REQUIRE(check.claim("6.5").largest);
  RobotCount most = 0;
  for (const FixpointSample& s : fixpoint_samples(few_samples(mc::Neighbourhood::four)))
    most = std::max(most, *std::max_element(s.start.begin(), s.start.end()));
  CHECK(most >= 200);
}

TEST_CASE("fixpoint search: the same figures from the same seed, for every thread count",
          "[proofs][fixpoint-search]") {
  FixpointSearchOptions options = few_samples(mc::Neighbourhood::eight);
  const FixpointCheck one = search_fixpoint(lemma_6_7(), options);
  options.threads = 2;
  const FixpointCheck two = search_fixpoint(lemma_6_7(), options);
  CHECK(one.result.verdict == two.result.verdict);
  CHECK(one.result.message == two.result.message);
  CHECK(one.result.figures == two.result.figures);
  CHECK(one.result.notes == two.result.notes);
  CHECK(two.result.threads == 2);
  options.seed = 2;
  const FixpointCheck other = search_fixpoint(lemma_6_7(), options);
  CHECK(other.result.figures != one.result.figures);
}

TEST_CASE("fixpoint search: the given curve, k and rho2 are the only ones drawn",
          "[proofs][fixpoint-search]") {
  FixpointSearchOptions options = few_samples(mc::Neighbourhood::four);
  options.min_side = options.max_side = 3;
  options.curves = {"hub-3"};
  options.grid_paths = false;
  options.ks = {2};
  options.rho2s = {{1, 2}};
  for (const FixpointSample& s : fixpoint_samples(options)) {
    CHECK(s.setting.m == 3);
    CHECK(s.setting.curve == "hub-3");
    CHECK(s.setting.k == 2);
    CHECK(s.setting.rho2 == mc::Rational(1, 2));
  }
  options.curves = {"zigzag"};
  CHECK_THROWS_AS(fixpoint_samples(options), std::invalid_argument);
}

TEST_CASE("fixpoint search: a violated claim is shrunk to the smallest counterexample",
          "[proofs][fixpoint-search]") {
  const FixpointLemma lemma = at_most_two_robots();
  FixpointSearchOptions options = few_samples(mc::Neighbourhood::four);
  options.samples = 5;
  const FixpointCheck check = search_fixpoint(lemma, options);
  CHECK(check.result.verdict == checker::Verdict::violated);
  REQUIRE(check.counterexample);
  // From hundreds of robots on a 2×2 or 3×3 grid to 3 robots on 1×1, k = 1, no curve.
  const BoundWitness& small = *check.counterexample;
  CHECK(small.robots() == 3);
  CHECK(small.setting.m == 1);
  CHECK(small.setting.k == 1);
  CHECK(small.setting.q == std::vector<QuantisedLength>{0});
  CHECK_THAT(small.setting.curve, Catch::StartsWith("shrunk from "));
  CHECK(small.measurement.value == 3);
  CHECK(check.result.message.rfind(
            "violated: two (smallest counterexample: 3 robots, m = 1, claim two); 5 samples", 0) ==
        0);
  CHECK(check.claim("two").violations > 0);
  CHECK(check.result.trace_role == "counterexample");
  CHECK(std::any_of(check.result.notes.begin(), check.result.notes.end(),
                    [](const std::string& note) {
                      return note.rfind("claim two: counterexample, m = 1", 0) == 0;
                    }));
  bool before = false;
  for (const auto& [name, value] : check.result.figures)
    before |= name == "smallest counterexamples before shrinking";
  CHECK(before);

  // Without shrinking: the smallest sample that fails, as found.
  options.shrink = false;
  const FixpointCheck raw = search_fixpoint(lemma, options);
  REQUIRE(raw.counterexample);
  CHECK(raw.counterexample->robots() > 3);
  CHECK(raw.counterexample->setting.m >= 2);
}

TEST_CASE("fixpoint search: shrink_fixpoint keeps what it is given when nothing is smaller",
          "[proofs][fixpoint-search]") {
  const FixpointLemma lemma = at_most_two_robots();
  FixpointSample sample;
  sample.setting.m = 1;
  sample.setting.curve = "none";
  sample.setting.q = {0};
  sample.start = {3};
  const auto found = fixpoint_violation(lemma, 0, sample);
  REQUIRE(found);
  const BoundWitness shrunk = shrink_fixpoint(lemma, 0, *found);
  CHECK(shrunk.start == Counts{3});
  CHECK(shrunk.setting.curve == "none");
  sample.start = {2};
  CHECK(!fixpoint_violation(lemma, 0, sample));
}

TEST_CASE("fixpoint search: a third of the samples are random grid paths, or the given curve",
          "[proofs][fixpoint-search]") {
  FixpointSearchOptions options = few_samples(mc::Neighbourhood::four);
  options.samples = 60;
  std::size_t paths = 0;
  for (const FixpointSample& s : fixpoint_samples(options))
    paths += s.setting.curve.rfind("a grid path through", 0) == 0 ? 1 : 0;
  CHECK(paths >= 10);
  CHECK(paths <= 35);
  options.given_curve = GivenCurve{"mine", 2, {0, 1, 2, 0}};
  for (const FixpointSample& s : fixpoint_samples(options)) {
    CHECK(s.setting.m == 2);
    CHECK(s.setting.curve == "mine");
    CHECK(s.setting.q == std::vector<QuantisedLength>{0, 1, 2, 0});
  }
}
