// The partial-order reduction on untimed automata (checker/zero_time_reduction.hpp): every
// state is reduced; a progress measure lets the stabilisation check decide on the reduced
// graph (checker/stabilisation_without_cycles.hpp) and a halt flag stay out of the
// dependencies.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "checker/checks.hpp"
#include "checker/property.hpp"
#include "checker/trace.hpp"
#include "tests/checker/helpers.hpp"
#include "tioa/successors.hpp"

using namespace checker;
using checker_test::with_por;
using tioa::Automaton;
using tioa::Params;
using tioa::State;

namespace {

// `n` robots, each counting its own steps from 0 to `k` (step_i). With `quitting`, a robot
// that has not moved may quit instead (x_i := k + 1: it never gets there). With a
// `limit`, a robot's step from x_i = limit meets a bound: it sets `overflow` (the model's
// halt flag) instead, and every step is disabled after.
struct Counters {
  Automaton system{"counters"};
  tioa::VariableArray<int> x;
  tioa::Variable<bool> overflow;
  int n = 0, k = 0;
};

struct CountersSpec {
  int n = 3, k = 2;
  bool quitting = false;
  int limit = -1; // -1: none
  bool measure = true;
  bool halt_flag = true;
  bool bad_measure = false; // a measure that a quit does not increase
};

Counters counters(const CountersSpec& spec) {
  Counters c;
  c.n = spec.n;
  c.k = spec.k;
  Automaton& a = c.system;
  c.x = a.integers("x", static_cast<std::size_t>(spec.n), 0, spec.k + 1, 0);
  const int limit = spec.limit;
  c.overflow = a.boolean("overflow", false);
  const auto x = c.x;
  const auto overflow = c.overflow;
  const int k = spec.k;
  const tioa::ParamRange robot{"i", 0, spec.n - 1};
  a.internal("step", {robot})
      .pre([=](const State& s, const Params& p) { return !s[overflow] && s[x[p[0]]] < k; })
      .eff([=](State& s, const Params& p) {
        if (s[x[p[0]]] == limit)
          s[overflow] = true;
        else
          s[x[p[0]]] = s[x[p[0]]] + 1;
      })
      .footprint([=](const Params& p, tioa::Footprint& f) {
        f.reads(overflow).reads(x[p[0]]).writes(x[p[0]]);
        if (limit >= 0)
          f.sets(overflow, true);
      });
  if (spec.quitting)
    a.internal("quit", {robot})
        .pre([=](const State& s, const Params& p) { return !s[overflow] && s[x[p[0]]] == 0; })
        .eff([=](State& s, const Params& p) { s[x[p[0]]] = k + 1; })
        .footprint([=](const Params& p, tioa::Footprint& f) {
          f.reads(overflow).reads(x[p[0]]).writes(x[p[0]]);
        });
  if (spec.halt_flag)
    a.set_halt_flag(overflow);
  if (spec.measure) {
    const int n = spec.n;
    const bool bad = spec.bad_measure;
    a.set_progress_measure([=](const State& s) {
      std::uint64_t sum = s[overflow] ? 1000 : 0;
      for (int i = 0; i < n; ++i)
        sum += static_cast<std::uint64_t>(s[x[i]] == k + 1 ? (bad ? 0 : k + 1) : s[x[i]]);
      return sum;
    });
  }
  return c;
}

tioa::StatePredicate all_done(const Counters& c) {
  return [x = c.x, n = c.n, k = c.k](const State& s) {
    for (int i = 0; i < n; ++i)
      if (s[x[i]] != k)
        return false;
    return true;
  };
}

bool replays(const Automaton& system, const PropertyResult& r) {
  const tioa::SuccessorGenerator generator(system);
  std::string why;
  return r.trace && replay(generator, *r.trace, &why);
}

} // namespace

TEST_CASE("untimed: independent steps are explored in one order, end states kept",
          "[por][untimed]") {
  const Counters c = counters({});
  const PropertyResult full = check_no_deadlock(c.system, with_por(false), all_done(c), "done");
  const PropertyResult reduced = check_no_deadlock(c.system, with_por(true), all_done(c), "done");
  CHECK(full.verdict == Verdict::holds);
  CHECK(reduced.verdict == Verdict::holds);
  CHECK(full.states == 27);   // (k + 1)^n
  CHECK(reduced.states == 7); // one order: n k + 1 states
  CHECK(reduced.reduced_states > 0);
  // Without the `done` exemption the end state is a deadlock, found both ways.
  const PropertyResult stuck = check_no_deadlock(c.system, with_por(true));
  CHECK(stuck.verdict == Verdict::violated);
  CHECK(replays(c.system, stuck));
}

TEST_CASE("untimed: the reduction finds the invariant violations a full search finds",
          "[por][untimed]") {
  const Counters c = counters({});
  const auto x = c.x;
  // x_0 + x_1 == 3 is reachable only through some interleavings of the two robots.
  const tioa::StatePredicate not_three = [=](const State& s) { return s[x[0]] + s[x[1]] != 3; };
  const PropertyResult full = check_invariant(c.system, not_three, with_por(false));
  const PropertyResult reduced = check_invariant(c.system, not_three, with_por(true));
  CHECK(full.verdict == Verdict::violated);
  CHECK(reduced.verdict == Verdict::violated);
  CHECK(replays(c.system, reduced));
  const tioa::StatePredicate bounded = [=](const State& s) { return s[x[2]] <= 2; };
  const PropertyResult holds = check_invariant(c.system, bounded, with_por(true));
  CHECK(holds.verdict == Verdict::holds);
  CHECK(holds.states < 27);
}

TEST_CASE("untimed with a progress measure: stabilisation decided on the reduced graph",
          "[por][untimed]") {
  SECTION("every execution ends in L") {
    const Counters c = counters({});
    const PropertyResult full = check_stabilisation(c.system, all_done(c), with_por(false));
    const PropertyResult reduced = check_stabilisation(c.system, all_done(c), with_por(true));
    CHECK(full.verdict == Verdict::holds);
    CHECK(full.worst_time == std::optional<std::uint64_t>(6)); // in L after n k steps
    CHECK(reduced.verdict == Verdict::holds);
    CHECK(reduced.states < full.states);
    CHECK_FALSE(reduced.worst_time);     // not measured on the reduced graph
    REQUIRE(replays(c.system, reduced)); // a witness: an execution to its end, in L
    CHECK(reduced.trace_kind == "end");
    CHECK(all_done(c)(State(reduced.trace->steps.back().state.data(), 0)));
  }
  SECTION("a robot that quits ends an execution outside L: found, with a replaying trace") {
    const Counters c = counters({.quitting = true});
    const PropertyResult full = check_stabilisation(c.system, all_done(c), with_por(false));
    const PropertyResult reduced = check_stabilisation(c.system, all_done(c), with_por(true));
    CHECK(full.verdict == Verdict::violated);
    CHECK(reduced.verdict == Verdict::violated);
    CHECK(reduced.states < full.states);
    REQUIRE(replays(c.system, reduced));
    const auto& last = reduced.trace->steps.back().state;
    CHECK_FALSE(all_done(c)(State(last.data(), 0)));
  }
  SECTION("without a measure the full check runs, and measures the worst time") {
    const Counters c = counters({.measure = false});
    const PropertyResult r = check_stabilisation(c.system, all_done(c), with_por(true));
    CHECK(r.verdict == Verdict::holds);
    CHECK(r.worst_time == std::optional<std::uint64_t>(6));
    CHECK_FALSE(r.por);
    CHECK(r.states == 27);
  }
}

TEST_CASE("a progress measure that a step does not increase is a model error", "[por][untimed]") {
  const Counters c = counters({.quitting = true, .bad_measure = true});
  CHECK_THROWS_AS(check_stabilisation(c.system, all_done(c), with_por(false)), tioa::ModelError);
  CHECK_THROWS_AS(check_stabilisation(c.system, all_done(c), with_por(true)), tioa::ModelError);
}

TEST_CASE("a halt flag stays out of the dependencies, and a bound met is still found",
          "[por][untimed]") {
  // Every step reads the flag and may set it (robot 0's step from x_0 = 1 meets the
  // bound). As a plain variable (no progress measure) it makes every step depend on
  // every other; as a halt flag it does not, and the bound is still met.
  Property p;
  p.name = "all done at the end";
  p.kind = PropertyKind::stabilisation;
  p.bound_name = "the limit";
  for (const bool measure : {true, false}) {
    INFO("measure " << measure);
    CountersSpec spec;
    spec.limit = 1;
    spec.measure = measure;
    const Counters c = counters(spec);
    p.predicate = all_done(c);
    p.beyond_bound = [overflow = c.overflow](const State& s) { return s[overflow]; };
    Property invariant = p;
    invariant.kind = PropertyKind::invariant;
    invariant.predicate = [x = c.x](const State& s) { return s[x[0]] <= 2; };
    for (const Property& property : {p, invariant}) {
      const PropertyResult full = run_property(c.system, property, with_por(false));
      const PropertyResult reduced = run_property(c.system, property, with_por(true));
      CHECK(full.verdict == Verdict::incomplete);
      CHECK(reduced.verdict == Verdict::incomplete);
      if (measure)
        CHECK(reduced.states < full.states);
      else
        CHECK(reduced.states == full.states);
    }
  }
}

TEST_CASE("a step enabled where the halt flag is set is a model error", "[por][untimed]") {
  Counters c = counters({});
  // A step whose guard forgets the flag.
  const auto overflow = c.overflow;
  c.system.internal("rogue")
      .pre([](const State&, const Params&) { return true; })
      .eff([=](State& s, const Params&) { s[overflow] = true; })
      .footprint([=](const Params&, tioa::Footprint& f) { f.sets(overflow, true); });
  c.system.set_progress_measure([=](const State& s) { return s[overflow] ? 1u : 0u; });
  CHECK_THROWS_AS(check_invariant(
                      c.system, [](const State&) { return true; }, with_por(true)),
                  tioa::ModelError);
}
