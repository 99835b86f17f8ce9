// Partial-order reduction of zero-time steps (checker/zero_time_reduction.hpp) on the
// built-in models: on every suite entry of a timed model whose check may use it
// (invariants, deadlocks and time-locks), the same verdict with and without it; with it
// the result says so, and a counterexample is a trace of the model.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "checker/property.hpp"
#include "checker/trace.hpp"
#include "tests/checker/helpers.hpp"

namespace {

// Runs `property` of the model built with `settings` without and with the reduction.
std::pair<checker::PropertyResult, checker::PropertyResult>
both_ways(const std::string& model, const std::vector<std::string>& settings,
          const std::string& property) {
  const auto& definition = catalogue::builtin_models().find(model);
  const auto instance = definition.build(catalogue::resolve_params(definition, settings));
  for (const auto& p : instance.properties)
    if (p.name == property) {
      checker::ExploreOptions off, on;
      on.por = true;
      return {checker::run_property(instance.system, p, off),
              checker::run_property(instance.system, p, on)};
    }
  FAIL("no property " << property);
  throw;
}

bool may_reduce(const checker::Property& p) {
  return p.kind == checker::PropertyKind::invariant || p.kind == checker::PropertyKind::deadlock ||
         (p.kind == checker::PropertyKind::custom && p.name == "no-timelock");
}

} // namespace

TEST_CASE("the suite's invariants and time-locks: the same verdicts with and without --por",
          "[catalogue][por]") {
  int compared = 0, too_large = 0;
  for (const auto& definition : catalogue::builtin_models().models())
    for (const auto& entry : definition.suite) {
      std::vector<std::string> settings;
      for (const auto& [name, value] : entry.params)
        settings.push_back(name + "=" + value.text());
      const auto instance = definition.build(catalogue::resolve_params(definition, settings));
      if (!instance.system.timed())
        continue;
      for (const auto& p : instance.properties) {
        if (p.name != entry.property || !may_reduce(p))
          continue;
        INFO(definition.name << " " << p.name);
        checker::ExploreOptions off, on;
        on.por = true;
        // The full graphs of vlayer-mc's five-robot entries are far larger than this: for
        // them there is nothing to compare with (the registry's suite test runs them reduced).
        off.limits.max_states = 300'000;
        const checker::PropertyResult full = checker::run_property(instance.system, p, off);
        if (full.message.find("state limit reached") != std::string::npos) {
          ++too_large;
          continue;
        }
        const checker::PropertyResult reduced = checker::run_property(instance.system, p, on);
        CHECK(reduced.verdict == full.verdict);
        CHECK(reduced.verdict == entry.expected);
        CHECK(reduced.por);
        CHECK_FALSE(full.por);
        CHECK(reduced.states <= full.states);
        if (reduced.trace && p.kind != checker::PropertyKind::custom) {
          std::string why;
          CHECK(checker::replay(tioa::SuccessorGenerator(instance.system), *reduced.trace, &why));
          INFO(why);
        }
        ++compared;
      }
    }
  CHECK(compared >= 4);
  CHECK(too_large <= 2); // the two five-robot entries at most
}

// [long] (opt-in: ctest -L long): about 90 s on two threads in a Release build.
TEST_CASE("the suite's timed stabilisation checks: the same verdicts and worst times with "
          "--por all",
          "[catalogue][por][long]") {
  // Every suite entry of a timed model whose property measures stabilisation (Def 3.5, and
  // Lemma 7.3 built on it; Theorem 7.5's first part is the same check, its known LMC makes
  // it slow), on fewer sampled start states where the model samples them.
  int compared = 0, reduced = 0;
  for (const auto& definition : catalogue::builtin_models().models())
    for (const auto& entry : definition.suite) {
      std::vector<std::string> settings;
      bool samples = false;
      for (const auto& [name, value] : entry.params) {
        samples = samples || name == "samples";
        settings.push_back(name + "=" + (name == "samples" ? std::string("5") : value.text()));
      }
      const auto instance = definition.build(catalogue::resolve_params(definition, settings));
      if (!instance.system.timed())
        continue;
      for (const auto& p : instance.properties) {
        const bool measures =
            p.kind == checker::PropertyKind::stabilisation || p.name == "lemma-7.3";
        if (p.name != entry.property || !measures)
          continue;
        INFO(definition.name << " " << p.name << (samples ? " (5 samples)" : ""));
        checker::ExploreOptions off, all;
        off.threads = all.threads = 2;
        all.por = all.por_stabilisation = true;
        const checker::PropertyResult full = checker::run_property(instance.system, p, off);
        const checker::PropertyResult on = checker::run_property(instance.system, p, all);
        CHECK(on.verdict == full.verdict);
        CHECK(on.worst_time == full.worst_time);
        reduced += on.reduced_states > 0 ? 1 : 0;
        ++compared;
      }
    }
  CHECK(compared >= 4);
  CHECK(reduced >= 4);
}

// [slow]: over 10 s under the sanitizers (tools/run-tests.sh skips it there).
TEST_CASE("vlayer-mc: fewer states and the same time-lock verdict with --por",
          "[catalogue][vlayer_mc][por][slow]") {
  // 1x2 with one robot: 2,706 states in full, 419 reduced (repaired variant); with two
  // robots and with faults (tens of thousands of states) the reduction must keep the
  // verdict too. The checks reduce states where time can pass as well (the vn-update
  // deliveries commute with a tick); a reduction that keeps them (the helper's) keeps
  // every one of them.
  for (const auto& settings : std::vector<std::vector<std::string>>{
           {}, {"robots=2"}, {"robot_faults=1"}, {"vsa_faults=1"}}) {
    const auto [full, reduced] = both_ways("vlayer-mc", settings, "no-timelock");
    INFO((settings.empty() ? std::string("1x2-r1") : settings.front()));
    CHECK(reduced.verdict == full.verdict);
    CHECK(reduced.verdict == checker::Verdict::holds);
    CHECK(reduced.states < full.states);
    CHECK(reduced.reduced_states > 0);
    const auto& definition = catalogue::builtin_models().find("vlayer-mc");
    const auto instance = definition.build(catalogue::resolve_params(definition, settings));
    CHECK(checker_test::time_passing_states(instance.system, true) ==
          checker_test::time_passing_states(instance.system, false));
  }
  // The paper's CN and VN declare narrower footprints than the repaired ones (a GPSupdate
  // writes x and clock only), so more steps commute: 284 states against 419 (391 and
  // 630 when states where time can pass were expanded in full).
  const auto [full, reduced] = both_ways("vlayer-mc", {}, "no-timelock");
  CHECK(full.states == 2706);
  CHECK(reduced.states == 284);
  const auto [full_repaired, reduced_repaired] =
      both_ways("vlayer-mc", {"cn_repair=1", "vn_repair=1"}, "no-timelock");
  CHECK(full_repaired.states == 2706);
  CHECK(reduced_repaired.states == 419);
}

// [slow]: about 10 s here, minutes under the sanitizers.
TEST_CASE("vn-layer: its footprints let the reduction act, with the same verdicts",
          "[catalogue][vn-layer][por][slow]") {
  // 2x1, every placement: 105,854 states in full, 90,247 reduced (no-timelock); the
  // invariants read more, so fewer steps commute with what they read.
  for (const std::string property : {"no-timelock", "round-timing", "y-consistency"}) {
    INFO(property);
    const auto [full, reduced] = both_ways("vn-layer", {}, property);
    CHECK(full.states == 105854);
    CHECK(reduced.verdict == full.verdict);
    CHECK(reduced.verdict == checker::Verdict::holds);
    CHECK(reduced.states <= full.states);
    if (property == "no-timelock")
      CHECK(reduced.states == 90247);
  }
  const auto& definition = catalogue::builtin_models().find("vn-layer");
  const auto instance = definition.build(catalogue::resolve_params(definition, {}));
  CHECK(checker_test::time_passing_states(instance.system, true) ==
        checker_test::time_passing_states(instance.system, false));
  // A violation found on the reduced graph is a trace of the model.
  const auto [full_any, reduced_any] = both_ways("vn-layer", {"vn_fail=any"}, "round-timing");
  CHECK(full_any.verdict == checker::Verdict::violated);
  REQUIRE(reduced_any.verdict == checker::Verdict::violated);
  REQUIRE(reduced_any.trace);
  const auto any = definition.build(catalogue::resolve_params(definition, {"vn_fail=any"}));
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(any.system), *reduced_any.trace, &why));
  INFO(why);
}
