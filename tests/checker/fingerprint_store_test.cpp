// The fingerprint store (checker/fingerprint.hpp, level_states.hpp): the same ids, parents
// and counts as the exact store for every thread count, traces rebuilt by re-execution
// that replay, verdicts (a property that holds is incomplete, a violation is violated), the
// omission probability, and the checks that refuse it.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "checker/checks.hpp"
#include "checker/fingerprint.hpp"
#include "checker/property.hpp"
#include "checker/reach.hpp"
#include "checker/trace.hpp"
#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

ExploreOptions options_for(StoreKind store, unsigned threads = 1) {
  ExploreOptions options;
  options.store = store;
  options.threads = threads;
  return options;
}

Exploration explore_in(const tioa::Automaton& a, const ExploreOptions& options,
                       const ExploreHooks& hooks = {}) {
  const tioa::SuccessorGenerator generator(a);
  return explore(generator, a.start(), options, hooks);
}

// The fingerprint run found what the exact run found, with the same ids: each id holds the
// fingerprint of the exact run's state with that id.
void require_same_as_exact(const Exploration& exact, const Exploration& fp) {
  REQUIRE(fp.fingerprints());
  REQUIRE(fp.store.words() == 1);
  REQUIRE(fp.store.size() == exact.store.size());
  CHECK(fp.start_states == exact.start_states);
  CHECK(fp.edges == exact.edges);
  CHECK(fp.expanded == exact.expanded);
  CHECK(fp.depth == exact.depth);
  CHECK(fp.stop == exact.stop);
  CHECK(fp.found == exact.found);
  CHECK(fp.stuck == exact.stuck);
  CHECK(fp.parent == exact.parent);
  bool same_ids = true;
  for (StateId id = 0; id < exact.store.size(); ++id)
    same_ids = same_ids &&
               fp.store.state(id)[0] == fingerprint(exact.store.state(id), exact.store.words());
  CHECK(same_ids);
}

void require_same_trace(const Trace& a, const Trace& b) {
  REQUIRE(a.steps.size() == b.steps.size());
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    CHECK(a.steps[i].action == b.steps[i].action);
    CHECK(a.steps[i].time == b.steps[i].time);
    CHECK(a.steps[i].state == b.steps[i].state);
  }
}

} // namespace

TEST_CASE("fingerprint: independent of the table's hash, and the omission probability",
          "[checker][fingerprint]") {
  const Word a[2] = {1, 2}, b[2] = {2, 1};
  CHECK(fingerprint(a, 2) != hash_state(a, 2));
  CHECK(fingerprint(a, 2) != fingerprint(b, 2));
  CHECK(fingerprint(a, 1) != fingerprint(a, 2));
  // n (n - 1) / 2 / 2^64.
  CHECK(omission_probability(0) == 0);
  CHECK(omission_probability(1) == 0);
  CHECK(omission_probability(2) == Approx(1.0 / 18446744073709551616.0));
  CHECK(omission_probability(std::uint64_t{1} << 32) == Approx(0.5).epsilon(1e-6));
  CHECK(omission_probability(11112321) == Approx(3.347e-6).epsilon(1e-3));
  CHECK(format_probability(omission_probability(11112321)) == "3.3e-06");
}

TEST_CASE("fingerprint store: the ids, parents and counts of the exact store, for 1, 2 and 4 "
          "threads",
          "[checker][fingerprint][threads]") {
  SECTION("Fischer N=6: levels of up to 9817 new states, inserted concurrently") {
    const auto fischer = fischer::build(6, 1, 2);
    const Exploration exact = explore_in(fischer.system, options_for(StoreKind::exact));
    CHECK(exact.store.size() == 65299); // tools/reference/peer_models.py
    for (unsigned threads : {1u, 2u, 4u}) {
      INFO(threads << " threads");
      require_same_as_exact(
          exact, explore_in(fischer.system, options_for(StoreKind::fingerprint, threads)));
    }
  }
  SECTION("token ring N=7 K=6: 279936 start states") {
    const auto ring = token_ring::build(7, 6);
    const Exploration exact = explore_in(ring.system, options_for(StoreKind::exact));
    for (unsigned threads : {1u, 2u})
      require_same_as_exact(exact,
                            explore_in(ring.system, options_for(StoreKind::fingerprint, threads)));
  }
  SECTION("the state limit, inside a level of more than 4096 states") {
    const auto fischer = fischer::build(6, 1, 2);
    ExploreOptions options = options_for(StoreKind::exact);
    options.limits.max_states = 30000;
    const Exploration exact = explore_in(fischer.system, options);
    REQUIRE(exact.stop == StopReason::state_limit);
    for (unsigned threads : {1u, 2u}) {
      ExploreOptions fp = options_for(StoreKind::fingerprint, threads);
      fp.limits.max_states = 30000;
      require_same_as_exact(exact, explore_in(fischer.system, fp));
    }
  }
  SECTION("the first target, from a level of more than 4096 states") {
    const auto fischer = fischer::build(6, 1, 2);
    const auto& a = fischer.system;
    const auto locations = slots_named(a, "loc"), clocks = slots_named(a, "c");
    ExploreHooks hooks; // three processes waiting, all with clock >= 2
    hooks.target = [&](const Word* s) {
      int waiting = 0;
      for (std::size_t p = 0; p < locations.size(); ++p)
        waiting += State(s, 0).code(locations[p]) == 2 && State(s, 0).code(clocks[p]) >= 2 ? 1 : 0;
      return waiting == 3;
    };
    const Exploration exact = explore_in(a, options_for(StoreKind::exact), hooks);
    REQUIRE(exact.found);
    const tioa::SuccessorGenerator generator(a);
    for (unsigned threads : {1u, 2u, 4u}) {
      INFO(threads << " threads");
      const Exploration fp = explore_in(a, options_for(StoreKind::fingerprint, threads), hooks);
      require_same_as_exact(exact, fp);
      CHECK(fp.found_state == stored(exact, *exact.found));
      require_same_trace(trace_to(generator, exact, *exact.found),
                         trace_to(generator, fp, *fp.found));
    }
  }
}

TEST_CASE("fingerprint store: traces rebuilt by re-execution are the exact store's",
          "[checker][fingerprint][trace]") {
  const auto fischer = fischer::build(3, 1, 2);
  const auto& a = fischer.system;
  const tioa::SuccessorGenerator generator(a);
  const Exploration exact = explore_in(a, options_for(StoreKind::exact));
  const Exploration fp = explore_in(a, options_for(StoreKind::fingerprint));
  REQUIRE(fp.store.size() == 357);
  for (StateId id = 0; id < fp.store.size(); ++id) {
    const Trace trace = trace_to(generator, fp, id);
    std::string why;
    REQUIRE(replay(generator, trace, &why));
    require_same_trace(trace_to(generator, exact, id), trace);
  }
}

TEST_CASE("fingerprint store: the verdicts of invariants and deadlocks",
          "[checker][fingerprint][checks]") {
  const ExploreOptions fp = options_for(StoreKind::fingerprint);
  SECTION("an invariant that holds is incomplete, up to hash collisions") {
    const auto fischer = fischer::build(4, 1, 2);
    const PropertyResult exact =
        check_invariant(fischer.system, fischer.at_most_one_in_cs, options_for(StoreKind::exact));
    const PropertyResult r = check_invariant(fischer.system, fischer.at_most_one_in_cs, fp);
    CHECK(exact.verdict == Verdict::holds);
    CHECK(exact.store == "exact");
    CHECK_FALSE(exact.omission_probability);
    CHECK(r.verdict == Verdict::incomplete);
    CHECK(r.store == "fingerprint");
    CHECK(r.states == exact.states);
    CHECK(r.edges == exact.edges);
    REQUIRE(r.omission_probability);
    CHECK(*r.omission_probability == omission_probability(exact.states));
    CHECK(r.message == "holds up to hash collisions, omission probability ≤ " +
                           format_probability(*r.omission_probability) + ": " + exact.message);
  }
  SECTION("a violated invariant is violated, with the exact store's trace") {
    const auto fischer = fischer::build(2, 2, 1); // B < A: mutual exclusion fails
    const PropertyResult exact =
        check_invariant(fischer.system, fischer.at_most_one_in_cs, options_for(StoreKind::exact));
    for (unsigned threads : {1u, 2u}) {
      const PropertyResult r = check_invariant(fischer.system, fischer.at_most_one_in_cs,
                                               options_for(StoreKind::fingerprint, threads));
      CHECK(r.verdict == Verdict::violated);
      CHECK(r.states == exact.states);
      REQUIRE(r.trace);
      CHECK(r.trace->length() == exact.trace->length());
      require_same_trace(*exact.trace, *r.trace);
      const tioa::SuccessorGenerator generator(fischer.system);
      CHECK(replay(generator, *r.trace, nullptr));
    }
  }
  SECTION("a deadlock is violated, with a trace to the first stuck state") {
    const PropertyResult exact = check_no_deadlock(diamond(), options_for(StoreKind::exact));
    const PropertyResult r = check_no_deadlock(diamond(), fp);
    CHECK(r.verdict == Verdict::violated);
    REQUIRE(r.trace);
    require_same_trace(*exact.trace, *r.trace);
  }
  SECTION("no time-lock is incomplete, up to hash collisions") {
    const auto ring = token_ring::build(5, 4);
    const PropertyResult r = check_no_deadlock(ring.system, fp);
    CHECK(r.verdict == Verdict::incomplete);
    CHECK(r.states == 1024);
    CHECK(r.message.rfind("holds up to hash collisions, omission probability ≤ ", 0) == 0);
  }
  SECTION("a start state that breaks the invariant: a trace of no step") {
    const PropertyResult r = check_invariant(
        diamond(), [](const tioa::State&) { return false; }, fp);
    CHECK(r.verdict == Verdict::violated);
    REQUIRE(r.trace);
    CHECK(r.trace->length() == 0);
  }
  SECTION("a limit: incomplete for the limit, with the probability beside it") {
    ExploreOptions limited = fp;
    limited.limits.max_states = 100;
    const auto fischer = fischer::build(4, 1, 2);
    const PropertyResult r = check_invariant(fischer.system, fischer.at_most_one_in_cs, limited);
    CHECK(r.verdict == Verdict::incomplete);
    CHECK(r.message.rfind("state limit reached after 100 states", 0) == 0);
    CHECK(r.omission_probability);
  }
}

TEST_CASE("fingerprint store: the memory limit holds", "[checker][fingerprint][limits]") {
  const auto fischer = fischer::build(6, 1, 2);
  ExploreOptions options = options_for(StoreKind::fingerprint, 2);
  options.limits.max_memory_bytes = 400 << 10;
  const Exploration ex = explore_in(fischer.system, options);
  CHECK(ex.stop == StopReason::memory_limit);
  CHECK(ex.peak_memory_bytes <= options.limits.max_memory_bytes);
}

TEST_CASE("fingerprint store: the checks that read states or edges after the search refuse it",
          "[checker][fingerprint][checks]") {
  const ExploreOptions fp = options_for(StoreKind::fingerprint);
  const auto ring = token_ring::build(4, 3);
  const tioa::StatePredicate legal = [](const tioa::State&) { return true; };
  CHECK_THROWS_AS(check_stabilisation(ring.system, legal, fp), std::invalid_argument);
  CHECK_THROWS_AS(check_legal_set(ring.system, legal, fp), std::invalid_argument);
  CHECK_THROWS_AS(check_transitivity(ring.system, legal, "L1", legal, "L2", fp),
                  std::invalid_argument);
  CHECK_THROWS_AS(R(ring.system, fp), std::invalid_argument);
  ExploreHooks edges;
  edges.record_edges = true;
  CHECK_THROWS_AS(explore_in(ring.system, fp, edges), std::invalid_argument);
  ExploreHooks canonical;
  canonical.canonical = [](Word*) {};
  CHECK_THROWS_AS(explore_in(ring.system, fp, canonical), std::invalid_argument);

  Property stabilisation{"convergence", "", PropertyKind::stabilisation, legal, "L", {}, ""};
  CHECK_THROWS_AS(run_property(ring.system, stabilisation, fp), std::invalid_argument);
  Property invariant{"some", "", PropertyKind::invariant, legal, "L", {}, ""};
  Property deadlock{"no-deadlock", "", PropertyKind::deadlock, {}, "", {}, ""};
  Property custom{"lemma", "", PropertyKind::custom, {}, "", {}, ""};
  CHECK(runs_on_fingerprint_store(invariant));
  CHECK(runs_on_fingerprint_store(deadlock));
  CHECK_FALSE(runs_on_fingerprint_store(custom));
  custom.fingerprint_store = true; // a custom check that runs check_no_deadlock, say
  CHECK(runs_on_fingerprint_store(custom));
}
