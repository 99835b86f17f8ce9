// The compressed store (checker/state_tree.hpp, ExploreOptions::store = compressed): the ids,
// parents, counts, edges and states of the exact store for every thread count, the same
// traces and verdicts (what holds, holds: the store is exact), also for the checks that
// read the stored states after the search.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "checker/checks.hpp"
#include "checker/property.hpp"
#include "checker/reach.hpp"
#include "checker/trace.hpp"
#include "models/fischer/fischer.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

constexpr int wide_top = 5;

ExploreOptions compressed_options(StoreKind store, unsigned threads = 1) {
  ExploreOptions options;
  options.store = store;
  options.threads = threads;
  return options;
}

template <class H = NoHooks>
Exploration explore_with(const tioa::Automaton& a, const ExploreOptions& options, const H& h = {}) {
  const tioa::SuccessorGenerator generator(a);
  return explore(generator, a.start(), options, h);
}

// The compressed run found what the exact run found, with the same ids: each id decodes to
// the exact run's state with that id.
void require_as_exact(const Exploration& exact, const Exploration& compressed) {
  REQUIRE(compressed.compressed());
  REQUIRE(compressed.store.size() == exact.store.size());
  CHECK(compressed.start_states == exact.start_states);
  CHECK(compressed.edges == exact.edges);
  CHECK(compressed.expanded == exact.expanded);
  CHECK(compressed.depth == exact.depth);
  CHECK(compressed.stop == exact.stop);
  CHECK(compressed.found == exact.found);
  CHECK(compressed.stuck == exact.stuck);
  CHECK(compressed.parent == exact.parent);
  CHECK(compressed.edge_offsets == exact.edge_offsets);
  CHECK(compressed.edge_targets == exact.edge_targets);
  std::vector<Word> buffer;
  bool same_states = true;
  for (StateId id = 0; id < exact.store.size(); ++id) {
    const Word* s = compressed.state(id, buffer);
    same_states = same_states && Words(s, s + exact.state_words) == stored(exact, id);
  }
  CHECK(same_states);
}

} // namespace

TEST_CASE("compressed store: the ids, parents, counts, edges and states of the exact store, for "
          "1, 2 and 4 threads",
          "[checker][compressed][threads]") {
  SECTION("six wide counters: three words, levels of thousands of states") {
    const tioa::Automaton a = wide_counters(6, wide_top, true);
    REQUIRE(a.words() == 3);
    const Exploration exact = explore_with(a, compressed_options(StoreKind::exact));
    CHECK(exact.store.size() == 46656); // 6^6
    for (unsigned threads : {1u, 2u, 4u}) {
      INFO(threads << " threads");
      const Exploration c = explore_with(a, compressed_options(StoreKind::compressed, threads));
      require_as_exact(exact, c);
      REQUIRE(c.tree);
      CHECK(c.tree->parts() > 0);
      CHECK(c.tree->parts() < exact.store.size()); // what the tree shares
    }
  }
  SECTION("with every edge recorded") {
    const tioa::Automaton a = wide_counters(5, wide_top, true);
    const Exploration exact =
        explore_with(a, compressed_options(StoreKind::exact), hooks().with_edges());
    REQUIRE(exact.edge_targets.size() == exact.edges);
    for (unsigned threads : {1u, 2u})
      require_as_exact(exact, explore_with(a, compressed_options(StoreKind::compressed, threads),
                                           hooks().with_edges()));
  }
  SECTION("a one-word model: the store holds the states themselves") {
    const auto fischer = fischer::build(6, 1, 2);
    const Exploration exact = explore_with(fischer.system, compressed_options(StoreKind::exact));
    const Exploration c =
        explore_with(fischer.system, compressed_options(StoreKind::compressed, 2));
    CHECK_FALSE(c.tree);
    require_as_exact(exact, c);
  }
  SECTION("the state limit, inside a level of more than 4096 states") {
    const tioa::Automaton a = wide_counters(6, wide_top, true);
    ExploreOptions options = compressed_options(StoreKind::exact);
    options.limits.max_states = 30000;
    const Exploration exact = explore_with(a, options);
    REQUIRE(exact.stop == StopReason::state_limit);
    for (unsigned threads : {1u, 2u}) {
      ExploreOptions compressed = compressed_options(StoreKind::compressed, threads);
      compressed.limits.max_states = 30000;
      require_as_exact(exact, explore_with(a, compressed));
    }
  }
  SECTION("the first target, from a level of more than 4096 states, and its trace") {
    const tioa::Automaton a = wide_counters(6, wide_top, true);
    const auto x0 = slot_of(a, "x0"), x5 = slot_of(a, "x5");
    ExploreHooks h;
    h.target = [&](const Word* s) {
      return State(s, 0).code(x0) == wide_top && State(s, 0).code(x5) == 3;
    };
    const Exploration exact = explore_with(a, compressed_options(StoreKind::exact), h);
    REQUIRE(exact.found);
    const tioa::SuccessorGenerator generator(a);
    for (unsigned threads : {1u, 2u, 4u}) {
      INFO(threads << " threads");
      const Exploration c = explore_with(a, compressed_options(StoreKind::compressed, threads), h);
      require_as_exact(exact, c);
      const Trace ours = trace_to(generator, c, *c.found);
      const Trace theirs = trace_to(generator, exact, *exact.found);
      REQUIRE(ours.steps.size() == theirs.steps.size());
      for (std::size_t i = 0; i < ours.steps.size(); ++i) {
        CHECK(ours.steps[i].action == theirs.steps[i].action);
        CHECK(ours.steps[i].state == theirs.steps[i].state);
      }
      CHECK(replay(generator, ours, nullptr));
    }
  }
}

TEST_CASE("compressed store: the verdicts of invariants and deadlocks are the exact store's",
          "[checker][compressed][checks]") {
  const tioa::Automaton a = wide_counters(4, wide_top, true);
  const auto x1 = slot_of(a, "x1"), x3 = slot_of(a, "x3");
  SECTION("an invariant that holds holds, with a note on the parts") {
    const tioa::StatePredicate below = [&](const State& s) { return s.code(x1) <= wide_top; };
    const PropertyResult exact = check_invariant(a, below, compressed_options(StoreKind::exact));
    const PropertyResult r =
        check_invariant(a, below, compressed_options(StoreKind::compressed, 2));
    CHECK(exact.verdict == Verdict::holds);
    CHECK(r.verdict == Verdict::holds);
    CHECK(r.store == "compressed");
    CHECK_FALSE(r.omission_probability);
    CHECK(r.states == exact.states);
    CHECK(r.edges == exact.edges);
    CHECK(r.message == exact.message);
    bool noted = false;
    for (const std::string& note : r.notes)
      noted = noted || note.rfind("compressed store: " + std::to_string(r.states) +
                                      " states held as keys into ",
                                  0) == 0;
    CHECK(noted);
  }
  SECTION("a violated invariant is violated, with the exact store's trace") {
    const tioa::StatePredicate never_both = [&](const State& s) {
      return !(s.code(x1) == wide_top && s.code(x3) == wide_top);
    };
    const PropertyResult exact =
        check_invariant(a, never_both, compressed_options(StoreKind::exact));
    REQUIRE(exact.verdict == Verdict::violated);
    for (unsigned threads : {1u, 2u}) {
      const PropertyResult r =
          check_invariant(a, never_both, compressed_options(StoreKind::compressed, threads));
      CHECK(r.verdict == Verdict::violated);
      CHECK(r.states == exact.states);
      REQUIRE(r.trace);
      REQUIRE(r.trace->steps.size() == exact.trace->steps.size());
      for (std::size_t i = 0; i < r.trace->steps.size(); ++i)
        CHECK(r.trace->steps[i].state == exact.trace->steps[i].state);
    }
  }
  SECTION("no deadlock holds; a deadlock is found with the exact store's trace") {
    CHECK(check_no_deadlock(a, compressed_options(StoreKind::compressed, 2)).verdict ==
          Verdict::holds);
    const PropertyResult exact = check_no_deadlock(diamond(), compressed_options(StoreKind::exact));
    const PropertyResult r =
        check_no_deadlock(diamond(), compressed_options(StoreKind::compressed));
    CHECK(r.verdict == Verdict::violated);
    REQUIRE(r.trace);
    CHECK(r.trace->steps.size() == exact.trace->steps.size());
  }
}

void require_same_trace(const PropertyResult& r, const PropertyResult& exact) {
  REQUIRE(r.trace.has_value() == exact.trace.has_value());
  if (!r.trace)
    return;
  CHECK(r.trace->loop_start == exact.trace->loop_start);
  REQUIRE(r.trace->steps.size() == exact.trace->steps.size());
  for (std::size_t i = 0; i < r.trace->steps.size(); ++i) {
    CHECK(r.trace->steps[i].action == exact.trace->steps[i].action);
    CHECK(r.trace->steps[i].state == exact.trace->steps[i].state);
  }
}

TEST_CASE("compressed store: the checks that read states or edges after the search give the "
          "exact store's results",
          "[checker][compressed][checks]") {
  SECTION("stabilisation that holds: the same worst time and witness") {
    const tioa::Automaton a = wide_counters(3, wide_top, false);
    const auto x0 = slot_of(a, "x0"), x1 = slot_of(a, "x1"), x2 = slot_of(a, "x2");
    const tioa::StatePredicate all_top = [&](const State& s) {
      return s.code(x0) == wide_top && s.code(x1) == wide_top && s.code(x2) == wide_top;
    };
    const PropertyResult exact =
        check_stabilisation(a, all_top, compressed_options(StoreKind::exact));
    REQUIRE(exact.verdict == Verdict::holds);
    REQUIRE(exact.worst_time == std::optional<std::uint64_t>(3 * wide_top));
    for (unsigned threads : {1u, 2u}) {
      const PropertyResult r =
          check_stabilisation(a, all_top, compressed_options(StoreKind::compressed, threads));
      CHECK(r.store == "compressed");
      CHECK(r.verdict == Verdict::holds);
      CHECK(r.worst_time == exact.worst_time);
      CHECK(r.states == exact.states);
      CHECK(r.edges == exact.edges);
      CHECK(r.message == exact.message);
      require_same_trace(r, exact);
    }
  }
  SECTION("stabilisation that fails: the same lasso") {
    const tioa::Automaton a = wide_counters(3, wide_top, true);
    const auto x0 = slot_of(a, "x0");
    const tioa::StatePredicate at_zero = [&](const State& s) { return s.code(x0) == 0; };
    const PropertyResult exact =
        check_stabilisation(a, at_zero, compressed_options(StoreKind::exact));
    REQUIRE(exact.verdict == Verdict::violated);
    REQUIRE(exact.trace);
    const PropertyResult r =
        check_stabilisation(a, at_zero, compressed_options(StoreKind::compressed, 2));
    CHECK(r.verdict == Verdict::violated);
    CHECK(r.trace_kind == exact.trace_kind);
    CHECK(r.message == exact.message);
    require_same_trace(r, exact);
  }
  SECTION("run_property takes it for every kind; only the fingerprint store is refused") {
    Property stabilisation;
    stabilisation.name = "stabilises";
    stabilisation.kind = PropertyKind::stabilisation;
    const auto x0 = slot_of(wide_counters(2, wide_top, true), "x0");
    stabilisation.predicate = [x0](const State& s) { return s.code(x0) <= wide_top; };
    const PropertyResult r = run_property(wide_counters(2, wide_top, true), stabilisation,
                                          compressed_options(StoreKind::compressed));
    CHECK(r.verdict == Verdict::holds);
    CHECK(r.store == "compressed");
    CHECK_NOTHROW(require_stored_states(compressed_options(StoreKind::compressed), "a check"));
    CHECK_THROWS_AS(require_stored_states(compressed_options(StoreKind::fingerprint), "a check"),
                    std::invalid_argument);
    CHECK_THROWS_WITH(run_property(wide_counters(2, wide_top, true), stabilisation,
                                   compressed_options(StoreKind::fingerprint)),
                      Catch::Contains("cannot run on the fingerprint store"));
  }
}

TEST_CASE("compressed store: Exploration::find and R(A) see the states the exact store holds",
          "[checker][compressed]") {
  const tioa::Automaton a = wide_counters(3, wide_top, true);
  const Exploration exact = explore_with(a, compressed_options(StoreKind::exact));
  const Exploration compressed = explore_with(a, compressed_options(StoreKind::compressed, 2));
  std::vector<Word> buffer;
  bool all_found = true;
  for (StateId id = 0; id < exact.store.size(); ++id) {
    const Word* s = exact.store.state(id);
    all_found = all_found && compressed.find(s) == std::optional<StateId>(id) &&
                exact.find(s) == std::optional<StateId>(id);
  }
  CHECK(all_found);
  Words absent = stored(exact, 0);
  State(absent.data(), 0).set_code(slot_of(a, "x1"), wide_top + 1); // never reached
  CHECK_FALSE(compressed.find(absent.data()));
  CHECK_FALSE(exact.find(absent.data()));
  Words huge = stored(exact, 0);
  State(huge.data(), 0).set_code(slot_of(a, "x1"), (1 << 30) - 1); // a part never stored
  CHECK_FALSE(compressed.find(huge.data()));

  const tioa::Automaton from_exact = R(a, compressed_options(StoreKind::exact));
  const tioa::Automaton from_compressed = R(a, compressed_options(StoreKind::compressed));
  const Exploration again_exact = explore_with(from_exact, compressed_options(StoreKind::exact));
  const Exploration again =
      explore_with(from_compressed, compressed_options(StoreKind::compressed));
  CHECK(again.start_states == exact.store.size());
  require_as_exact(again_exact, again);
}
