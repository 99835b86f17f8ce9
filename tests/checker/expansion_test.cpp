// Expansion (checker/expansion.hpp): a worker expands its chunk of the frontier and inserts
// the successors itself, each new state keeping the step that found it first; edges to
// known and to new states; the chunks of a level, expanded in parallel, find the same
// states with the same keys as one worker.
#include <catch2/catch.hpp>

#include <map>
#include <vector>

#include "checker/expansion.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

struct Setup {
  explicit Setup(tioa::Automaton automaton)
      : a(std::move(automaton)), generator(a), store(a.words()) {}

  // A state of the frontier (the frontier is the ids added, in order).
  StateId add(const Words& state) {
    const auto [id, fresh] = store.insert(state.data(), hash_state(state.data(), a.words()));
    if (fresh)
      parent.push_back(no_parent);
    return id;
  }
  // One worker expands the frontier (every state stored so far), within `share`.
  template <class Hooks>
  Worker expand(const Hooks& hooks, std::size_t share = MemoryBudget::unlimited) {
    Worker w(a.words());
    w.clear();
    w.allowance.begin_level(w.bytes(), share);
    GrowthGate gate = begin(1);
    w.expand(hooks, level(gate, 1), 0, first_new, true);
    gate.leave();
    return w;
  }
  // `workers` expand the frontier, as one level of an exploration.
  template <class Hooks> void run(std::span<Worker> workers, const Hooks& hooks) {
    GrowthGate gate = begin(workers.size());
    MemoryBudget budget(0, [] { return std::size_t{0}; });
    expand_level(workers, hooks, level(gate, workers.size()), budget);
  }
  GrowthGate begin(std::size_t workers) {
    first_new = static_cast<StateId>(store.size());
    store.set_inserters(static_cast<std::uint32_t>(workers), id_block_size);
    discovery.begin(first_new);
    discovery.make_room(store.id_limit());
    parent.grow(store.id_limit());
    return GrowthGate(workers, [this, workers] {
      std::function<bool(StateId)> holds;
      if (workers > 1)
        holds = [this](StateId id) {
          return id < discovery.first() || discovery.key_of(id) != Discovery::hole;
        };
      store.make_room(64, holds);
      parent.grow(store.id_limit());
      discovery.make_room(store.id_limit());
      return true;
    });
  }
  Level level(GrowthGate& gate, std::size_t workers) {
    return Level{generator, store,   discovery, parent,   gate,    0,       first_new, 0,
                 0,         workers, no_limits, progress, signals, nullptr, nullptr};
  }
  Words stored(StateId id) const { return Words(store.state(id), store.state(id) + a.words()); }

  tioa::Automaton a;
  tioa::SuccessorGenerator generator;
  Limits no_limits;
  StateStore store;
  Discovery discovery;
  MappedVector<StateId> parent; // written by one worker alone
  StateId first_new = 0;
  Progress progress{false, ""};
  LevelSignals signals;
};

Words flags(const tioa::Automaton& d, bool a, bool b) {
  return make_state(d, [&](State& s) {
    s.set(tioa::Variable<bool>{d.layout().find("a")->slot()}, a);
    s.set(tioa::Variable<bool>{d.layout().find("b")->slot()}, b);
  });
}

} // namespace

TEST_CASE("expansion: successors not in the store are inserted, in order, with their parents",
          "[checker][expansion]") {
  Setup s(diamond());
  s.add(flags(s.a, false, false));
  const Worker w = s.expand(hooks());
  REQUIRE(s.store.size() == 3);
  CHECK(s.stored(1) == flags(s.a, true, false)); // setA, then setB
  CHECK(s.stored(2) == flags(s.a, false, true));
  CHECK(s.parent == std::vector<StateId>{no_parent, 0, 0}); // one worker writes them
  CHECK(w.edge_count == 2);
  CHECK(w.expanded == 1);
  CHECK(w.known_edges.empty());
  CHECK(w.new_edges.empty()); // edges only with record_edges
  CHECK(w.stuck.empty());
  CHECK(w.targets.empty());
  CHECK_FALSE(w.error);
}

TEST_CASE("expansion: edges to known states, stuck states, and the hooks", "[checker][expansion]") {
  Setup s(diamond());
  s.add(flags(s.a, false, false));
  SECTION("edges to states stored before the level and to new ones, with record_edges") {
    const StateId known = s.add(flags(s.a, true, false)); // in the frontier too
    const Worker w = s.expand(hooks().with_edges());
    // 00 -> 10 (known), 00 -> 01 (new: id 2), 10 -> 11 (new: id 3)
    REQUIRE(w.known_edges.size() == 1);
    CHECK(w.known_edges[0].from == 0);
    CHECK(w.known_edges[0].target() == known);
    CHECK(w.known_edges[0].duration() == 1); // untimed: a step is a unit
    REQUIRE(w.new_edges.size() == 2);
    CHECK(w.new_edges[0].from == 0);
    CHECK(w.new_edges[0].target() == 2);
    CHECK(w.new_edges[1].from == 1);
    CHECK(w.new_edges[1].target() == 3);
    CHECK(s.stored(2) == flags(s.a, false, true));
  }
  SECTION("a state with no successor is stuck") {
    s.store.truncate(0);
    const StateId stuck = s.add(flags(s.a, true, true));
    const Worker w = s.expand(hooks());
    CHECK(w.stuck == std::vector<StateId>{stuck});
    CHECK(w.expanded == 1);
    CHECK(w.edge_count == 0);
  }
  SECTION("expand: a state it refuses is skipped") {
    const Worker w = s.expand(hooks().with_expand([](const Word*) { return false; }));
    CHECK(w.expanded == 0);
    CHECK(s.store.size() == 1);
  }
  SECTION("target: asked of each new state") {
    const Words wanted = flags(s.a, false, true);
    const Worker w = s.expand(hooks().with_target(
        [&](const Word* state) { return std::equal(wanted.begin(), wanted.end(), state); }));
    CHECK(w.targets == std::vector<StateId>{2});
  }
  SECTION("canonical: successors are replaced by their representative before the lookup") {
    const Words representative = flags(s.a, true, false);
    s.expand(hooks().with_canonical(
        [&](Word* state) { std::copy(representative.begin(), representative.end(), state); }));
    CHECK(s.store.size() == 2); // both successors are 10
    CHECK(s.parent == std::vector<StateId>{no_parent, 0});
  }
}

TEST_CASE("expansion: a worker grows only within its allowance", "[checker][expansion]") {
  Setup s(diamond());
  s.add(flags(s.a, false, false));
  const Worker w = s.expand(hooks().with_edges(), 0);
  CHECK(s.signals.out_of_memory);
  CHECK(w.expanded == 0);
  CHECK(w.known_edges.capacity() == 0);
  CHECK(s.store.size() == 1);
}

TEST_CASE("expansion: a level cut into chunks finds what one worker finds, with the same parents",
          "[checker][expansion][threads]") {
  // x = 9000.. 3000 stored; dec takes x to x - 1 and x - 2: 2999 is found from 3001 (its
  // first step) and from 3000, 2998 from 3000.
  auto run = [](std::size_t used) {
    Setup s(countdown(9000, true));
    const tioa::Slot x = slot_of(s.a, "x");
    for (int value = 9000; value >= 3000; --value)
      s.add(make_state(s.a, [&](State& st) { st.set_code(x, value); }));
    std::vector<Worker> workers(used, Worker(s.a.words()));
    s.run(std::span<Worker>(workers), hooks().with_edges());
    // One worker writes the parents; several keep the first step of each new state, and
    // leave the ids of their blocks that no state took as holes.
    std::map<Words, StateId> parents;
    for (StateId id = s.first_new; id < s.store.size(); ++id) {
      if (used == 1)
        parents[s.stored(id)] = s.parent[id];
      else if (s.discovery.key_of(id) != Discovery::hole)
        parents[s.stored(id)] = Discovery::parent_of(s.discovery.key_of(id));
    }
    std::uint64_t edges = 0;
    for (const Worker& w : workers)
      edges += w.known_edges.size() + w.new_edges.size();
    return std::make_pair(parents, edges);
  };
  const auto one = run(1);
  CHECK(one.first.size() == 2);
  CHECK(one.first.begin()->second == 6000); // 2998's parent: 3000, the last of 6001
  CHECK(one.second == 2 * 6001);
  CHECK(run(2) == one);
  CHECK(run(3) == one);
}
