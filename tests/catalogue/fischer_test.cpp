// Fischer's mutual exclusion in discrete time (models/fischer/), pinned to the figures of
// tools/reference/peer_models.py, an independent brute-force enumerator that shares no
// code with the checker (`python3 tools/reference/peer_models.py --table --skip-large`).
#include <catch2/catch.hpp>

#include <algorithm>

#include "catalogue/fischer.hpp"
#include "checker/property.hpp"
#include "tests/checker/helpers.hpp"

using checker::PropertyResult;
using checker::Verdict;

namespace {

struct Row {
  int n, a, b;
  std::uint64_t states, edges, tick_loops, bad_states;
  std::optional<std::size_t> shortest; // length of a shortest trace to two in CS
};

// All figures from tools/reference/peer_models.py (an independent brute-force enumerator).
const std::vector<Row> reference{
    {2, 1, 2, 59, 126, 11, 0, std::nullopt},
    {3, 1, 2, 357, 917, 31, 0, std::nullopt},
    {4, 1, 2, 2055, 6072, 79, 0, std::nullopt},
    {5, 1, 2, 11633, 38697, 191, 0, std::nullopt},
    {2, 2, 2, 108, 245, 17, 2, 10},
    {3, 2, 2, 1081, 3084, 73, 51, 10},
    {2, 2, 1, 112, 281, 17, 2, 8},
    {3, 2, 1, 1153, 3720, 73, 63, 8},
};

const checker::Property& property(const catalogue::ModelInstance& m, const std::string& name) {
  for (const auto& p : m.properties)
    if (p.name == name)
      return p;
  throw std::logic_error("test: no property " + name);
}

// How many processes are in CS; `locations` are the slots of the array loc[...].
int in_cs(const std::vector<tioa::Slot>& locations, const tioa::Word* s) {
  int count = 0;
  for (const auto& loc : locations)
    count += tioa::State(s, 0).code(loc) == 3 ? 1 : 0; // IDLE, REQ, WAIT, CS
  return count;
}

} // namespace

TEST_CASE("fischer: exact counts for every reference size", "[models][fischer]") {
  for (const Row& row : reference) {
    INFO("N=" << row.n << " A=" << row.a << " B=" << row.b);
    const catalogue::ModelInstance m = catalogue::build_fischer(row.n, row.a, row.b);
    const auto locations = checker_test::slots_named(m.system, "loc");
    REQUIRE(locations.size() == static_cast<std::size_t>(row.n));
    CHECK_FALSE(m.quantum.empty()); // timed: time is quanta
    const tioa::SuccessorGenerator generator(m.system);
    checker::ExploreHooks hooks;
    hooks.record_edges = true;
    const checker::Exploration ex = checker::explore(generator, m.system.start(), {}, hooks);
    CHECK(ex.complete());
    CHECK(ex.start_states == 1);
    CHECK(ex.store.size() == row.states);
    CHECK(ex.edges == row.edges);
    CHECK(ex.edge_targets.size() == row.edges);
    std::uint64_t loops = 0;
    for (checker::StateId id = 0; id < ex.store.size(); ++id)
      for (const std::uint32_t to : ex.steps_from(id))
        loops += (to & ~checker::Edge::timed_bit) == id ? 1 : 0;
    CHECK(loops == row.tick_loops);
    std::uint64_t bad = 0;
    for (checker::StateId id = 0; id < ex.store.size(); ++id)
      bad += in_cs(locations, ex.store.state(id)) >= 2 ? 1 : 0;
    CHECK(bad == row.bad_states);
    CHECK(ex.stuck.empty()); // no deadlocks in any instance
  }
}

TEST_CASE("fischer: mutex and no-timelock hold with A=1, B=2", "[models][fischer]") {
  for (const Row& row : reference) {
    if (row.shortest)
      continue;
    INFO("N=" << row.n);
    const catalogue::ModelInstance m = catalogue::build_fischer(row.n, row.a, row.b);
    const PropertyResult mutex = checker::run_property(m.system, property(m, "mutex"), {});
    CHECK(mutex.verdict == Verdict::holds);
    CHECK(mutex.states == row.states);
    CHECK(mutex.edges == row.edges);
    CHECK(mutex.time_unit == "quanta");
    const PropertyResult lock = checker::run_property(m.system, property(m, "no-timelock"), {});
    CHECK(lock.verdict == Verdict::holds);
    CHECK(lock.states == row.states);
    CHECK(lock.message == "no time-lock in " + std::to_string(row.states) + " reachable states");
  }
}

TEST_CASE("fischer: with B <= A mutex fails, with a shortest trace that replays",
          "[models][fischer]") {
  for (const Row& row : reference) {
    if (!row.shortest)
      continue;
    INFO("N=" << row.n << " A=" << row.a << " B=" << row.b);
    const catalogue::ModelInstance m = catalogue::build_fischer(row.n, row.a, row.b);
    const auto locations = checker_test::slots_named(m.system, "loc");
    REQUIRE(locations.size() == static_cast<std::size_t>(row.n));
    for (unsigned threads : {1u, 2u}) {
      checker::ExploreOptions options;
      options.threads = threads;
      const PropertyResult r = checker::run_property(m.system, property(m, "mutex"), options);
      CHECK(r.verdict == Verdict::violated);
      REQUIRE(r.trace);
      CHECK(r.trace_kind == "invariant");
      CHECK(r.trace->length() == *row.shortest);
      CHECK(in_cs(locations, r.trace->steps.back().state.data()) == 2);
      for (std::size_t i = 0; i + 1 < r.trace->steps.size(); ++i)
        CHECK(in_cs(locations, r.trace->steps[i].state.data()) < 2);
      const tioa::SuccessorGenerator generator(m.system);
      std::string why;
      const bool replayed = checker::replay(generator, *r.trace, &why);
      INFO(why);
      CHECK(replayed);
      // The trace waits B ticks before each enter: at least 2B quanta in all.
      CHECK(r.trace->steps.back().time >= static_cast<std::uint64_t>(2 * row.b));
    }
    // No time-lock either: the failure is the protocol's, not the model's.
    CHECK(checker::run_property(m.system, property(m, "no-timelock"), {}).verdict ==
          Verdict::holds);
  }
}
