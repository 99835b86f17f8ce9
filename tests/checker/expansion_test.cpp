// Expansion (checker/expansion.hpp): a worker turns its chunk of the frontier into
// candidates and edges to known states; the chunks of a level, expanded in parallel, give
// what one worker gives.
#include <catch2/catch.hpp>

#include <vector>

#include "checker/expansion.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

struct Setup {
  explicit Setup(tioa::Automaton automaton)
      : a(std::move(automaton)), generator(a), store(a.words()) {}

  StateId add(const Words& state) {
    const StateId id = store.insert(state.data(), hash_state(state.data(), a.words())).first;
    frontier.push_back(id);
    return id;
  }
  Level level(std::size_t workers = 1) {
    return Level{generator, store, frontier, 0, workers, 0, progress, signals};
  }
  template <class Hooks>
  Worker expand(const Hooks& hooks, std::size_t share = MemoryBudget::unlimited) {
    Worker w(a.words());
    w.clear();
    w.allowance.begin_level(w.bytes(), share);
    w.expand(hooks, level(), 0, frontier.size(), true);
    return w;
  }

  tioa::Automaton a;
  tioa::SuccessorGenerator generator;
  StateStore store;
  std::vector<StateId> frontier;
  Progress progress{false, ""};
  LevelSignals signals;
};

Words flags(const tioa::Automaton& d, bool a, bool b) {
  return make_state(d, [&](State& s) {
    s.set(tioa::Variable<bool>{d.layout().find("a")->slot()}, a);
    s.set(tioa::Variable<bool>{d.layout().find("b")->slot()}, b);
  });
}

Words at(const Worker& w, std::size_t c, std::uint32_t words) {
  return Words(w.states[c], w.states[c] + words);
}

} // namespace

TEST_CASE("expansion: successors not in the store become candidates, in order",
          "[checker][expansion]") {
  Setup s(diamond());
  s.add(flags(s.a, false, false));
  const Worker w = s.expand(hooks());
  REQUIRE(w.candidates.size() == 2);
  CHECK(at(w, 0, s.a.words()) == flags(s.a, true, false)); // setA, then setB
  CHECK(at(w, 1, s.a.words()) == flags(s.a, false, true));
  CHECK(w.candidates[0].from == 0);
  CHECK(w.candidates[0].duration == 1); // untimed: a step is a unit
  CHECK(w.candidates[0].hash == hash_state(w.states[0], s.a.words()));
  CHECK_FALSE(w.candidates[0].target);
  CHECK(w.edge_count == 2);
  CHECK(w.expanded == 1);
  CHECK(w.edges.empty());
  CHECK(w.stuck.empty());
  CHECK_FALSE(w.error);
  CHECK(s.store.size() == 1); // the store is only read
}

TEST_CASE("expansion: edges to known states, stuck states, and the hooks", "[checker][expansion]") {
  Setup s(diamond());
  s.add(flags(s.a, false, false));
  const StateId known = s.add(flags(s.a, true, false));
  s.frontier = {0};
  SECTION("a successor in the store is an edge (recorded only with record_edges)") {
    const Worker plain = s.expand(hooks());
    CHECK(plain.candidates.size() == 1);
    CHECK(plain.edges.empty());
    CHECK(plain.edge_count == 2);
    const Worker w = s.expand(hooks().with_edges());
    REQUIRE(w.edges.size() == 1);
    CHECK(w.edges[0].from == 0);
    CHECK(w.edges[0].target() == known);
    CHECK(w.edges[0].duration() == 1);
    CHECK(at(w, 0, s.a.words()) == flags(s.a, false, true));
  }
  SECTION("a state with no successor is stuck") {
    s.frontier = {s.add(flags(s.a, true, true))};
    const Worker w = s.expand(hooks());
    CHECK(w.stuck == std::vector<StateId>{s.frontier[0]});
    CHECK(w.expanded == 1);
    CHECK(w.edge_count == 0);
  }
  SECTION("expand: a state it refuses is skipped") {
    const Worker w = s.expand(hooks().with_expand([](const Word*) { return false; }));
    CHECK(w.expanded == 0);
    CHECK(w.candidates.empty());
  }
  SECTION("target: asked of each candidate") {
    const Words wanted = flags(s.a, false, true);
    const Worker w = s.expand(hooks().with_target(
        [&](const Word* state) { return std::equal(wanted.begin(), wanted.end(), state); }));
    REQUIRE(w.candidates.size() == 1);
    CHECK(w.candidates[0].target);
  }
  SECTION("canonical: successors are replaced by their representative before the lookup") {
    const Words representative = flags(s.a, true, false);
    const Worker w = s.expand(hooks().with_canonical(
        [&](Word* state) { std::copy(representative.begin(), representative.end(), state); }));
    CHECK(w.candidates.empty()); // both successors are the known 10
  }
}

TEST_CASE("expansion: a worker grows only within its allowance", "[checker][expansion]") {
  Setup s(diamond());
  s.add(flags(s.a, false, false));
  const Worker w = s.expand(hooks(), 0);
  CHECK(s.signals.out_of_memory);
  CHECK(w.expanded == 0);
  CHECK(w.candidates.capacity() == 0);
}

TEST_CASE("expansion: a level cut into chunks gives what one worker gives, in order",
          "[checker][expansion][threads]") {
  // x = 6, 5, 4 stored; dec takes x to x - 1 and x - 2: candidates 3 (from 5 and 4), 2.
  Setup s(countdown(6, true));
  const tioa::Slot x = slot_of(s.a, "x");
  auto number = [&](int value) {
    return make_state(s.a, [&](State& st) { st.set_code(x, value); });
  };
  for (int value : {6, 5, 4})
    s.add(number(value));
  auto run = [&](std::size_t used) {
    std::vector<Worker> workers(used, Worker(s.a.words()));
    MemoryBudget budget(0, [] { return std::size_t{0}; });
    expand_level(std::span<Worker>(workers), hooks().with_edges(), s.level(used), budget);
    std::vector<std::pair<StateId, Words>> candidates;
    std::vector<Edge> edges;
    for (const Worker& w : workers) {
      for (std::size_t c = 0; c < w.candidates.size(); ++c)
        candidates.emplace_back(w.candidates[c].from, at(w, c, s.a.words()));
      edges.insert(edges.end(), w.edges.begin(), w.edges.end());
    }
    return std::make_pair(candidates, edges.size());
  };
  const auto one = run(1);
  CHECK(one.first ==
        std::vector<std::pair<StateId, Words>>{{1, number(3)}, {2, number(3)}, {2, number(2)}});
  CHECK(one.second == 3); // 6 -> 5, 6 -> 4, 5 -> 4
  CHECK(run(2) == one);
  CHECK(run(3) == one);
}
