// Theorem 7.8 as the composition of Theorem 7.5, Lemma 7.7 and Lemma 7.6
// (proofs/theorem_7_8.hpp): the verdicts combine as the paper's argument does.
#include <catch2/catch.hpp>

#include "proofs/theorem_7_8.hpp"

using checker::PropertyResult;
using checker::Verdict;

namespace {

PropertyResult part(const char* name, Verdict verdict,
                    checker::Starts starts = checker::Starts::all, std::uint64_t count = 1) {
  PropertyResult r;
  r.name = name;
  r.kind = "stabilisation";
  r.verdict = verdict;
  r.message = std::string(name) + " says so";
  r.states = 10;
  r.coverage = {starts, count, std::nullopt, "the starts", ""};
  return r;
}

} // namespace

TEST_CASE("theorem-7.8 holds only when the three parts hold", "[proofs][vlayer]") {
  const PropertyResult holds =
      vlayer_mc::theorem_7_8(part("theorem-7.5", Verdict::holds), part("lemma-7.6", Verdict::holds),
                             part("lemma-7.7", Verdict::holds));
  CHECK(holds.name == "theorem-7.8");
  CHECK(holds.verdict == Verdict::holds);
  CHECK(holds.kind == "composition");
  CHECK(holds.states == 30);

  const PropertyResult sampled = vlayer_mc::theorem_7_8(
      part("theorem-7.5", Verdict::incomplete, checker::Starts::sampled, 1000),
      part("lemma-7.6", Verdict::holds), part("lemma-7.7", Verdict::holds));
  CHECK(sampled.verdict == Verdict::incomplete);
  CHECK(sampled.coverage.starts == checker::Starts::sampled);
  CHECK_THAT(sampled.message, Catch::Contains("theorem-7.5 did not cover its whole statement"));
}

TEST_CASE("theorem-7.8 is violated by the first failing step, with its trace", "[proofs][vlayer]") {
  PropertyResult related = part("lemma-7.7", Verdict::violated);
  related.kind = "simulation";
  related.trace = checker::Trace{};
  related.trace_kind = "invariant";
  const PropertyResult r = vlayer_mc::theorem_7_8(part("theorem-7.5", Verdict::incomplete),
                                                  part("lemma-7.6", Verdict::violated), related);
  CHECK(r.verdict == Verdict::violated);
  CHECK(r.kind == "simulation"); // the kind its trace is of
  CHECK(r.trace);
  CHECK(r.trace_kind == "invariant");
  CHECK_THAT(r.message, Catch::StartsWith("violated: the step 'every ResetMC state R_MC-related"));
  CHECK_THAT(r.message, Catch::Contains("(lemma-7.7: lemma-7.7 says so)"));
  CHECK_THAT(r.notes.at(2), Catch::StartsWith("lemma-7.7 violated (every ResetMC state"));
}
