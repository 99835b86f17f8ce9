// The distributed checks (checker/distributed_checks.hpp, closure_scan.hpp) against one
// process's, with the ranks as threads of this process (thread_ranks.hpp): the same
// verdict, message, counts, depth, coverage and trace, for 1 to 4 ranks.

#include <catch2/catch.hpp>

#include "checker/checks.hpp"
#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"
#include "tests/checker/helpers.hpp"
#include "tests/checker/thread_ranks.hpp"
#include "tioa/compose.hpp"

using namespace checker;
using namespace checker_test;

namespace {

// What a distributed run must give as one process does (not the seconds, threads, ranks).
void require_same(const PropertyResult& one, const PropertyResult& other, int ranks) {
  INFO(ranks << " ranks: " << one.message << " / " << other.message);
  CHECK(other.ranks == static_cast<unsigned>(ranks));
  CHECK(other.verdict == one.verdict);
  CHECK(other.message == one.message);
  CHECK(other.states == one.states);
  CHECK(other.edges == one.edges);
  CHECK(other.depth == one.depth);
  CHECK(other.por == one.por);
  CHECK(other.reduced_states == one.reduced_states);
  CHECK(other.store == one.store);
  CHECK(other.omission_probability == one.omission_probability);
  CHECK(other.coverage.count == one.coverage.count);
  CHECK(other.coverage.of == one.coverage.of);
  REQUIRE(other.trace.has_value() == one.trace.has_value());
  if (!one.trace)
    return;
  REQUIRE(other.trace->steps.size() == one.trace->steps.size());
  for (std::size_t i = 0; i < one.trace->steps.size(); ++i) {
    CHECK(other.trace->steps[i].action == one.trace->steps[i].action);
    CHECK(other.trace->steps[i].time == one.trace->steps[i].time);
    CHECK(other.trace->steps[i].state == one.trace->steps[i].state);
  }
}

// Runs `check` on one process, then on 1 to 4 ranks, and compares every rank's result.
PropertyResult same_on_every_rank_count(const std::function<PropertyResult()>& check) {
  const PropertyResult one = check();
  for (int ranks = 1; ranks <= 4; ++ranks)
    for (const PropertyResult& r : ThreadRanks::run<PropertyResult>(ranks, check))
      require_same(one, r, ranks);
  return one;
}

// x in 0..2^18 - 1 counts up; L = every x but `hole`, so the step into the hole leaves L
// from the member just before it, hundreds of thousands of valuations into the scan.
tioa::Automaton counter_with_hole() {
  tioa::Automaton a("counter");
  const auto x = a.integer("x", 0, (1 << 18) - 1, 0);
  a.internal("up")
      .pre([=](const State& s, const Params&) { return s[x] < (1 << 18) - 1; })
      .eff([=](State& s, const Params&) { s[x] = s[x] + 1; });
  return a;
}

// The model error each rank's invariant check throws ("no error": none), for 1 to 4 ranks.
std::vector<std::string> model_errors(const tioa::Automaton& a, const StatePredicate& invariant) {
  std::vector<std::string> out;
  for (int ranks = 1; ranks <= 4; ++ranks)
    for (std::string& what : ThreadRanks::run<std::string>(ranks, [&] {
           try {
             check_invariant(a, invariant, {});
             return std::string("no error");
           } catch (const tioa::ModelError& e) {
             return std::string(e.what());
           }
         }))
      out.push_back(std::move(what));
  return out;
}

// y counts up to 5 and stops there: a deadlock five steps from the start.
tioa::Automaton counts_to_five() {
  tioa::Automaton stops("stops");
  const auto y = stops.integer("y", 0, 5, 0);
  stops.internal("inc")
      .pre([=](const State& s, const Params&) { return s[y] < 5; })
      .eff([=](State& s, const Params&) { s[y] = s[y] + 1; });
  return stops;
}

} // namespace

TEST_CASE("distributed: the legal-set closure as one process scans it",
          "[checker][distributed][legal_set]") {
  const auto ring = token_ring::build(5, 4);
  const StatePredicate one_privileged = [p = ring.privileges](const State& s) { return p(s) == 1; };
  SECTION("holds") {
    const PropertyResult r =
        same_on_every_rank_count([&] { return check_legal_set(ring.system, one_privileged, {}); });
    CHECK(r.verdict == Verdict::holds);
  }
  const tioa::Automaton counter = counter_with_hole();
  const auto x = slot_of(counter, "x");
  const StatePredicate legal = [=](const State& s) { return s.code(x) != 200000; };
  SECTION("a step out of L, several rounds into the scan") {
    const PropertyResult r =
        same_on_every_rank_count([&] { return check_legal_set(counter, legal, {}); });
    REQUIRE(r.verdict == Verdict::violated);
    CHECK(r.states == 200000); // the members 0 .. 199,999
    CHECK(value_of(counter, r.trace->steps[0].state, "x") == 199999);
  }
  SECTION("a state limit before the step out, and one after it") {
    for (const std::uint64_t limit : {150000u, 199999u, 200000u, 65536u * 3}) {
      ExploreOptions options;
      options.limits.max_states = limit;
      const PropertyResult r =
          same_on_every_rank_count([&] { return check_legal_set(counter, legal, options); });
      CHECK(r.verdict == (limit < 200000 ? Verdict::incomplete : Verdict::violated));
    }
  }
  SECTION("an empty legal set") {
    const PropertyResult r = same_on_every_rank_count(
        [&] { return check_legal_set(ring.system, [](const State&) { return false; }, {}); });
    CHECK(r.verdict == Verdict::violated);
  }
}

TEST_CASE("distributed: invariants and deadlocks as one process finds them",
          "[checker][distributed]") {
  const auto good = fischer::build(3, 1, 2);
  const auto bad = fischer::build(3, 2, 1); // the delay not above the bound: mutex fails
  SECTION("an invariant that holds, and one broken") {
    CHECK(same_on_every_rank_count([&] {
            return check_invariant(good.system, good.at_most_one_in_cs, {});
          }).verdict == Verdict::holds);
    const PropertyResult r = same_on_every_rank_count(
        [&] { return check_invariant(bad.system, bad.at_most_one_in_cs, {}); });
    CHECK(r.verdict == Verdict::violated);
  }
  SECTION("a state limit inside a level") {
    ExploreOptions options;
    options.limits.max_states = 100;
    options.por = false;
    CHECK(same_on_every_rank_count([&] {
            return check_invariant(good.system, good.at_most_one_in_cs, options);
          }).verdict == Verdict::incomplete);
  }
  SECTION("deadlocks: none in Fischer, and the token ring's first stuck state") {
    ExploreOptions options;
    options.por = false;
    CHECK(same_on_every_rank_count([&] {
            return check_no_deadlock(good.system, options);
          }).verdict == Verdict::holds);
    const tioa::Automaton stops = counts_to_five();
    const PropertyResult r =
        same_on_every_rank_count([&] { return check_no_deadlock(stops, options); });
    CHECK(r.verdict == Verdict::violated);
    CHECK(r.trace->length() == 5);
  }
}

TEST_CASE("distributed: threads within each rank change nothing",
          "[checker][distributed][threads]") {
  const auto good = fischer::build(4, 1, 2);
  const auto bad = fischer::build(4, 2, 1);
  for (const unsigned threads : {2u, 3u}) {
    ExploreOptions options;
    options.por = false;
    options.threads = threads;
    INFO(threads << " threads");
    CHECK(same_on_every_rank_count([&] {
            return check_invariant(good.system, good.at_most_one_in_cs, options);
          }).verdict == Verdict::holds);
    CHECK(same_on_every_rank_count([&] {
            return check_invariant(bad.system, bad.at_most_one_in_cs, options);
          }).verdict == Verdict::violated);
    CHECK(same_on_every_rank_count([&] {
            return check_no_deadlock(good.system, options);
          }).verdict == Verdict::holds);
    ExploreOptions limited = options;
    limited.limits.max_states = 500;
    CHECK(same_on_every_rank_count([&] {
            return check_invariant(good.system, good.at_most_one_in_cs, limited);
          }).verdict == Verdict::incomplete);
  }
}

TEST_CASE("distributed: a rank that fails stops every rank, none waits for it",
          "[checker][distributed][failure]") {
  // x counts up from 0 in two ways; the step from x = 5 fails in one of them, on the rank
  // that owns x = 5 only.
  const auto counter = [](bool out_of_memory) {
    tioa::Automaton a("fails");
    const auto x = a.integer("x", 0, 9, 0);
    a.internal("up")
        .pre([=](const State& s, const Params&) { return s[x] < 9; })
        .eff([=](State& s, const Params&) {
          if (s[x] == 5) {
            if (out_of_memory)
              throw std::bad_alloc();
            throw tioa::ModelError("x = 5 has no successor in this model");
          }
          s[x] = s[x] + 1;
        });
    return a;
  };
  const tioa::Automaton model_error = counter(false), memory = counter(true);
  const StatePredicate anything = [](const State&) { return true; };
  SECTION("a model's error: every rank throws it, as one process does") {
    CHECK_THROWS_AS(check_invariant(model_error, anything, {}), tioa::ModelError);
    for (const std::string& what : model_errors(model_error, anything))
      CHECK(what == "x = 5 has no successor in this model");
  }
  SECTION("the checked predicate's error, on the rank that owns the state") {
    const tioa::Slot x = slot_of(memory, "x");
    const StatePredicate throws = [=](const State& s) -> bool {
      if (s.code(x) == 3)
        throw tioa::ModelError("the predicate cannot read x = 3");
      return true;
    };
    for (const std::string& what : model_errors(model_error, throws))
      CHECK(what == "the predicate cannot read x = 3");
  }
  SECTION("out of memory on one rank: incomplete on every rank, saying which") {
    for (int ranks = 1; ranks <= 4; ++ranks)
      for (const PropertyResult& r : ThreadRanks::run<PropertyResult>(
               ranks, [&] { return check_invariant(memory, anything, {}); })) {
        CHECK(r.verdict == Verdict::incomplete);
        CHECK(r.message.rfind("memory limit reached", 0) == 0);
        REQUIRE(r.notes.size() == 1);
        CHECK(r.notes[0].find("stopped the run: out of memory") != std::string::npos);
        CHECK(r.notes[0].find(" of " + std::to_string(ranks)) != std::string::npos);
      }
  }
}

TEST_CASE("distributed: with the partial-order reduction, the reduced graph of one process",
          "[checker][distributed][por]") {
  // Workers that must each work once an instant, independently: the reduction takes one
  // order of their steps where the full search takes every interleaving.
  std::vector<tioa::Automaton> parts;
  for (int i = 0; i < 4; ++i) {
    tioa::Automaton a("w" + std::to_string(i));
    const auto due = a.boolean("due", true);
    const auto count = a.integer("count", 0, 3, 0);
    a.internal("work" + std::to_string(i))
        .pre([=](const State& s, const Params&) { return s[due]; })
        .eff([=](State& s, const Params&) {
          s[due] = false;
          s[count] = std::min<int>(s[count] + 1, 3);
        });
    a.trajectories([=](State& s) { s[due] = true; }, [=](const State& s) { return s[due]; });
    parts.push_back(a);
  }
  const tioa::Automaton workers = tioa::compose("workers", parts);
  const tioa::Slot first_count = slot_of(workers, "w0.count");
  const StatePredicate below_three = [=](const State& s) { return s.code(first_count) < 3; };
  for (const unsigned threads : {1u, 2u}) {
    ExploreOptions options = with_por(true);
    options.threads = threads;
    const PropertyResult holds =
        same_on_every_rank_count([&] { return check_no_deadlock(workers, options); });
    CHECK(holds.verdict == Verdict::holds);
    CHECK(holds.reduced_states > 0);
    CHECK(holds.states < check_no_deadlock(workers, with_por(false)).states);
    const PropertyResult broken =
        same_on_every_rank_count([&] { return check_invariant(workers, below_three, options); });
    CHECK(broken.verdict == Verdict::violated);
    CHECK(broken.reduced_states > 0);
  }
}

TEST_CASE("distributed: on the fingerprint store, as one process",
          "[checker][distributed][store]") {
  const auto good = fischer::build(4, 1, 2);
  const auto bad = fischer::build(4, 2, 1);
  for (const unsigned threads : {1u, 2u}) {
    ExploreOptions options = with_por(false);
    options.threads = threads;
    options.store = StoreKind::fingerprint;
    const PropertyResult holds = same_on_every_rank_count(
        [&] { return check_invariant(good.system, good.at_most_one_in_cs, options); });
    CHECK(holds.verdict == Verdict::incomplete); // "holds up to hash collisions"
    CHECK(holds.store == "fingerprint");
    CHECK(holds.omission_probability.has_value());
    const PropertyResult broken = same_on_every_rank_count(
        [&] { return check_invariant(bad.system, bad.at_most_one_in_cs, options); });
    CHECK(broken.verdict == Verdict::violated);
    REQUIRE(broken.trace);
    CHECK(broken.trace->length() > 0);
    const tioa::Automaton stops = counts_to_five();
    const PropertyResult stuck =
        same_on_every_rank_count([&] { return check_no_deadlock(stops, options); });
    CHECK(stuck.verdict == Verdict::violated);
    CHECK(stuck.trace->length() == 5);
  }
}

namespace {

// wide_counters (helpers.hpp) counting to 40: a word of 2^31 or more goes into a table of
// the compressed store's tree, 41 · 41 of them for the first word, so the tables grow
// during the run.
constexpr int ranked_top = 40;

} // namespace

TEST_CASE("distributed: on the compressed store, as one process", "[checker][distributed][store]") {
  const tioa::Automaton cycles = wide_counters(3, ranked_top, true);
  const tioa::Automaton stops = wide_counters(3, ranked_top, false);
  const auto x0 = slot_of(cycles, "x0"), x1 = slot_of(cycles, "x1"), x2 = slot_of(cycles, "x2");
  const StatePredicate below_top = [&](const State& s) { return s.code(x0) < ranked_top; };
  const StatePredicate not_all_high = [&](const State& s) {
    return !(s.code(x0) > 30 && s.code(x1) > 30 && s.code(x2) > 30);
  };
  for (const unsigned threads : {1u, 2u}) {
    ExploreOptions options = with_por(false);
    options.threads = threads;
    options.store = StoreKind::compressed;
    const PropertyResult holds = same_on_every_rank_count([&] {
      return check_invariant(
          cycles, [](const State&) { return true; }, options);
    });
    CHECK(holds.verdict == Verdict::holds); // exact: what holds, holds
    CHECK(holds.store == "compressed");
    CHECK(holds.states == 41u * 41u * 41u);
    const PropertyResult broken =
        same_on_every_rank_count([&] { return check_invariant(cycles, below_top, options); });
    CHECK(broken.verdict == Verdict::violated);
    REQUIRE(broken.trace);
    CHECK(broken.trace->length() == ranked_top);
    const PropertyResult deep =
        same_on_every_rank_count([&] { return check_invariant(cycles, not_all_high, options); });
    CHECK(deep.verdict == Verdict::violated);
    const PropertyResult stuck =
        same_on_every_rank_count([&] { return check_no_deadlock(stops, options); });
    CHECK(stuck.verdict == Verdict::violated);
    REQUIRE(stuck.trace);
    CHECK(stuck.trace->length() == 3 * ranked_top);
  }
}
