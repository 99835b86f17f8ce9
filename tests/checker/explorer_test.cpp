// Breadth-first exploration (checker/explorer.hpp): exact counts on automata small enough
// to draw, the same result for every thread count, limits, hooks and stuck states.
#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>

#include "checker/explorer.hpp"
#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"
#include "tests/checker/helpers.hpp"

using namespace checker;
using namespace checker_test;

namespace {

Exploration run(const tioa::Automaton& a, const ExploreOptions& options = {},
                const ExploreHooks& hooks = {}) {
  const tioa::SuccessorGenerator generator(a);
  return explore(generator, a.start(), options, hooks);
}

ExploreOptions with_threads(unsigned threads) {
  ExploreOptions options;
  options.threads = threads;
  return options;
}

std::vector<std::tuple<StateId, StateId, std::uint32_t>> edges_of(const Exploration& ex) {
  std::vector<std::tuple<StateId, StateId, std::uint32_t>> out;
  for (StateId v = 0; v < ex.store.size(); ++v)
    for (const std::uint32_t to : ex.steps_from(v)) {
      const Edge e{v, to};
      out.emplace_back(e.from, e.target(), e.duration());
    }
  return out;
}

// The states an exploration stored, their ids and parents, and why it stopped.
void require_same_states(const Exploration& a, const Exploration& b) {
  REQUIRE(a.store.size() == b.store.size());
  REQUIRE(a.start_states == b.start_states);
  REQUIRE(a.depth == b.depth);
  REQUIRE(a.stop == b.stop);
  REQUIRE(a.found == b.found);
  REQUIRE(a.parent == b.parent);
  const std::size_t words = a.store.size() * a.store.words();
  REQUIRE(std::equal(a.store.state(0), a.store.state(0) + words, b.store.state(0)));
}

// The edges, expanded states and stuck states it counted.
void require_same_counts(const Exploration& a, const Exploration& b) {
  CHECK(a.edges == b.edges);
  CHECK(a.expanded == b.expanded);
  CHECK(a.stuck == b.stuck);
  // Edges may be recorded in another order, but each state's out-edges come in one order.
  auto sorted_by_source = [](std::vector<std::tuple<StateId, StateId, std::uint32_t>> e) {
    std::stable_sort(e.begin(), e.end(),
                     [](const auto& x, const auto& y) { return std::get<0>(x) < std::get<0>(y); });
    return e;
  };
  CHECK(a.edge_targets.size() == b.edge_targets.size());
  const bool same_edges = sorted_by_source(edges_of(a)) == sorted_by_source(edges_of(b));
  CHECK(same_edges);
}

// Everything an exploration produced that must not depend on the thread count.
void require_same(const Exploration& a, const Exploration& b) {
  require_same_states(a, b);
  require_same_counts(a, b);
}

} // namespace

TEST_CASE("explore: exact counts, ids and parents on the diamond", "[checker][explorer]") {
  const tioa::Automaton d = diamond();
  ExploreHooks hooks;
  hooks.record_edges = true;
  const Exploration ex = run(d, {}, hooks);

  CHECK(ex.stop == StopReason::finished);
  CHECK(ex.complete());
  CHECK(ex.store.size() == 4);
  CHECK(ex.start_states == 1);
  CHECK(ex.edges == 4);
  CHECK(ex.expanded == 4);
  CHECK(ex.depth == 3); // levels expanded: {00}, {10, 01}, {11}
  CHECK_FALSE(ex.found);
  CHECK(ex.threads == 1);

  // Ids in BFS order, successors in action order: 00, 10 (setA), 01 (setB), 11.
  auto at = [&](bool a, bool b) {
    return make_state(d, [&](State& s) {
      s.set(tioa::Variable<bool>{d.layout().find("a")->slot()}, a);
      s.set(tioa::Variable<bool>{d.layout().find("b")->slot()}, b);
    });
  };
  CHECK(stored(ex, 0) == at(false, false));
  CHECK(stored(ex, 1) == at(true, false));
  CHECK(stored(ex, 2) == at(false, true));
  CHECK(stored(ex, 3) == at(true, true));
  CHECK(ex.parent == std::vector<StateId>{no_parent, 0, 0, 1});
  CHECK(ex.stuck == std::vector<StateId>{3});

  auto edges = edges_of(ex);
  std::sort(edges.begin(), edges.end());
  CHECK(edges == std::vector<std::tuple<StateId, StateId, std::uint32_t>>{
                     {0, 1, 1}, {0, 2, 1}, {1, 3, 1}, {2, 3, 1}}); // untimed: a step is a unit
}

TEST_CASE("explore: choices and parameters each count as an edge", "[checker][explorer]") {
  SECTION("two choices that reach the same state are two edges") {
    // x in 0..4 from 0; step: x := min(x + 1 + choice, 4) for choice 0, 1.
    tioa::Automaton a("choices");
    const auto x = a.integer("x", 0, 4, 0);
    a.internal("step")
        .pre([=](const State& s, const Params&) { return s[x] < 4; })
        .choose(2, [=](State& s, const Params&, std::uint32_t c) {
          s[x] = std::min(s[x] + 1 + static_cast<int>(c), 4);
        });
    const Exploration ex = run(a);
    CHECK(ex.store.size() == 5);
    CHECK(ex.edges == 8); // 2 from each of 0..3, the two from 3 both to 4
    CHECK(ex.stuck == std::vector<StateId>{4});
    CHECK(ex.depth == 3); // levels expanded: {0}, {1, 2}, {3, 4}
  }
  SECTION("an input is driven with every value of its box") {
    // Inputs come from the environment: set(v) for v in 0..2 from every state.
    tioa::Automaton a("input");
    const auto x = a.integer("x", 0, 2, 0);
    a.input("set", {{"v", 0, 2}}).eff([=](State& s, const Params& p) { s[x] = p[0]; });
    const Exploration ex = run(a);
    CHECK(ex.store.size() == 3);
    CHECK(ex.edges == 9); // three per state, self-loops included
    CHECK(ex.stuck.empty());
  }
}

TEST_CASE("explore: ticks, stop-when and edge durations", "[checker][explorer]") {
  // A clock c (cap 2) from 0; time cannot pass at c == 2, where reset takes it back to 0.
  tioa::Automaton a("timer");
  const auto c = a.clock("c", 2, 0);
  a.internal("reset")
      .pre([=](const State& s, const Params&) { return s[c] == 2; })
      .eff([=](State& s, const Params&) { s[c] = 0; });
  a.trajectories([=](State& s) { s.advance(c); }, [=](const State& s) { return s[c] == 2; });
  ExploreHooks hooks;
  hooks.record_edges = true;
  const Exploration ex = run(a, {}, hooks);
  CHECK(ex.store.size() == 3);
  CHECK(ex.edges == 3);
  CHECK(ex.stuck.empty());
  auto edges = edges_of(ex);
  std::sort(edges.begin(), edges.end());
  // 0 -tick-> 1 -tick-> 2 -reset-> 0: ticks last one quantum, actions none.
  CHECK(edges ==
        std::vector<std::tuple<StateId, StateId, std::uint32_t>>{{0, 1, 1}, {1, 2, 1}, {2, 0, 0}});

  SECTION("a tick that changes nothing is a self-loop edge") {
    tioa::Automaton idle("idle");
    idle.boolean("b", false);
    idle.trajectories({});
    const Exploration e = run(idle);
    CHECK(e.store.size() == 1);
    CHECK(e.edges == 1);
    CHECK(e.stuck.empty());
  }
}

TEST_CASE("explore: start states are level 0, duplicates among them counted once",
          "[checker][explorer]") {
  const tioa::Automaton c = countdown(6);
  const Exploration ex = run(c);
  CHECK(ex.start_states == 7);
  CHECK(ex.store.size() == 7);
  CHECK(ex.edges == 6); // dec from 1..6
  CHECK(std::all_of(ex.parent.begin(), ex.parent.end(), [](StateId p) { return p == no_parent; }));
  CHECK(ex.stuck == std::vector<StateId>{0}); // x = 0 is the first start state

  // A start set that lists the same state twice.
  const tioa::Automaton d = diamond();
  const Words s = make_state(d, [](State&) {});
  Words list = s;
  list.insert(list.end(), s.begin(), s.end());
  const tioa::Automaton twice =
      tioa::Start(d, tioa::StartSet::listed(d.layout().bits(), d.words(), list, "twice"));
  const Exploration e = run(twice);
  CHECK(e.start_states == 1);
  CHECK(e.store.size() == 4);
}

TEST_CASE("explore: the same ids, parents, counts and target for 1, 2 and 4 threads",
          "[checker][explorer][threads]") {
  SECTION("token ring N=7 K=6: 279936 start states, so level 0 is expanded in parallel") {
    const auto ring = token_ring::build(7, 6);
    ExploreHooks hooks;
    hooks.record_edges = true;
    const Exploration one = run(ring.system, with_threads(1), hooks);
    // From tools/reference/peer_models.py (an independent brute-force enumerator).
    CHECK(one.store.size() == 279936);
    CHECK(one.edges == 1446336);
    for (unsigned threads : {2u, 4u}) {
      const Exploration many = run(ring.system, with_threads(threads), hooks);
      CHECK(many.threads == threads);
      require_same(one, many);
    }
  }
  SECTION("Fischer N=6: levels of up to 9817 new states are merged from several threads") {
    const auto fischer = fischer::build(6, 1, 2);
    ExploreHooks hooks;
    hooks.record_edges = true;
    const Exploration one = run(fischer.system, with_threads(1), hooks);
    // From tools/reference/peer_models.py (an independent brute-force enumerator).
    CHECK(one.store.size() == 65299);
    CHECK(one.edges == 241992);
    for (unsigned threads : {2u, 4u})
      require_same(one, run(fischer.system, with_threads(threads), hooks));
  }
  SECTION("Fischer N=7: the store grows many times while several workers insert") {
    // Regression: a table rebuilt during a level took the unused ids of the workers' id
    // blocks (stale states) for states, about one run in four with two threads.
    const auto fischer = fischer::build(7, 1, 2);
    const Exploration one = run(fischer.system, with_threads(1));
    CHECK(one.store.size() == 364129); // tools/reference/peer_models.py
    for (int repeat = 0; repeat < 3; ++repeat)
      for (unsigned threads : {2u, 4u})
        require_same(one, run(fischer.system, with_threads(threads)));
  }
  SECTION("Fischer N=6: the first target found") {
    const auto fischer = fischer::build(6, 1, 2);
    const auto& a = fischer.system;
    // A deep state: three processes waiting, all with clock >= 2.
    const auto locations = slots_named(a, "loc"), clocks = slots_named(a, "c");
    ExploreHooks hooks;
    hooks.target = [&](const Word* s) {
      int waiting = 0;
      for (std::size_t p = 0; p < locations.size(); ++p)
        waiting += State(s, 0).code(locations[p]) == 2 && State(s, 0).code(clocks[p]) >= 2 ? 1 : 0;
      return waiting == 3;
    };
    const Exploration one = run(a, with_threads(1), hooks);
    REQUIRE(one.found);
    CHECK(one.stop == StopReason::found);
    CHECK(one.complete());
    CHECK(one.depth > 5);
    for (unsigned threads : {2u, 4u}) {
      const Exploration many = run(a, with_threads(threads), hooks);
      CHECK(many.found == one.found);
      require_same(one, many);
    }
  }
}

TEST_CASE("explore: zero threads means one", "[checker][explorer][threads]") {
  const Exploration ex = run(diamond(), with_threads(0));
  CHECK(ex.threads == 1);
  CHECK(ex.store.size() == 4);
}

TEST_CASE("explore: a state limit stops the run, incomplete", "[checker][explorer][limits]") {
  const auto ring = token_ring::build(5, 4); // 1024 states, all start states
  ExploreOptions options;
  options.limits.max_states = 100;
  const Exploration ex = run(ring.system, options);
  CHECK(ex.stop == StopReason::state_limit);
  CHECK_FALSE(ex.complete());
  CHECK(ex.store.size() == 100); // never more than max_states states

  SECTION("also when the limit is reached after level 0") {
    const auto fischer = fischer::build(3, 1, 2); // 357 states from one
    options.limits.max_states = 50;
    const Exploration e = run(fischer.system, options);
    CHECK(e.stop == StopReason::state_limit);
    CHECK_FALSE(e.complete());
    CHECK(e.store.size() == 50);
    for (unsigned threads : {2u, 4u}) {
      options.threads = threads;
      const Exploration f = run(fischer.system, options);
      CHECK(f.stop == StopReason::state_limit);
      CHECK(f.store.size() == e.store.size());
    }
  }
  SECTION("the same states for every thread count when levels are merged in parallel") {
    const auto fischer = fischer::build(6, 1, 2);
    options.limits.max_states = 30000;
    const Exploration e = run(fischer.system, options);
    CHECK(e.stop == StopReason::state_limit);
    for (unsigned threads : {2u, 4u}) {
      options.threads = threads;
      require_same_states(e, run(fischer.system, options));
    }
  }
  SECTION("stop_at_state_limit: the last level is not finished, for any thread count") {
    const auto fischer = fischer::build(6, 1, 2);
    options.limits.max_states = 30000; // inside a level of more than 4096 states
    const Exploration finished = run(fischer.system, options);
    options.stop_at_state_limit = true;
    for (unsigned threads : {1u, 2u, 4u}) {
      INFO(threads << " threads");
      options.threads = threads;
      const Exploration e = run(fischer.system, options);
      CHECK(e.stop == StopReason::state_limit);
      CHECK_FALSE(e.complete());
      // Alone, the worker stops at the limit; with several, the ids the others took in
      // blocks but did not fill are dropped, and one may insert while another meets it.
      if (threads == 1)
        CHECK(e.store.size() == 30000);
      CHECK(e.store.size() <= 30000 + threads * id_block_size);
      CHECK(e.edges < finished.edges); // the level's other states were not expanded
    }
  }
  SECTION("a limit of exactly the state count changes nothing") {
    options.limits.max_states = 1024;
    const Exploration e = run(ring.system, options);
    CHECK(e.stop == StopReason::finished);
    CHECK(e.store.size() == 1024);
  }
}

TEST_CASE("explore: a run cut inside a parallel level counts the same for every thread count",
          "[checker][explorer][threads]") {
  // Regression: the merge loop once added a worker's counts only while it had not
  // stopped, so a state limit or a target hit in worker t dropped the counts of workers
  // t+1.., which with one thread are all counted.
  const auto fischer = fischer::build(6, 1, 2);
  ExploreHooks hooks;
  hooks.record_edges = true;
  SECTION("state limit") {
    ExploreOptions options;
    options.limits.max_states = 30000; // inside a level of more than 4096 states
    const Exploration one = run(fischer.system, options, hooks);
    REQUIRE(one.stop == StopReason::state_limit);
    for (unsigned threads : {2u, 4u}) {
      INFO(threads << " threads");
      options.threads = threads;
      const Exploration many = run(fischer.system, options, hooks);
      require_same_states(one, many);
      require_same_counts(one, many);
    }
  }
  SECTION("target") {
    // The target: the first state found from a level of more than 4096 states, so that
    // it is a candidate of the first worker and the other workers' counts are dropped.
    const auto& a = fischer.system;
    const Exploration full = run(a);
    std::vector<std::uint32_t> depth(full.store.size(), 0), level_size(64, 0);
    for (StateId id = 0; id < full.store.size(); ++id) {
      depth[id] = full.parent[id] == no_parent ? 0 : depth[full.parent[id]] + 1;
      ++level_size[depth[id]];
    }
    StateId first = 0;
    while (depth[first] == 0 || level_size[depth[first] - 1] < 4096)
      ++first;
    const Words target = stored(full, first);
    hooks.target = [&](const Word* s) { return std::equal(target.begin(), target.end(), s); };
    const Exploration one = run(a, {}, hooks);
    REQUIRE(one.found == first);
    for (unsigned threads : {2u, 4u}) {
      INFO(threads << " threads");
      const Exploration many = run(a, with_threads(threads), hooks);
      require_same_states(one, many);
      require_same_counts(one, many);
    }
  }
}

TEST_CASE("explore: time and memory limits stop the run, incomplete",
          "[checker][explorer][limits]") {
  const auto fischer = fischer::build(3, 1, 2);
  SECTION("time") {
    ExploreOptions options;
    options.limits.max_seconds = 1e-9;
    const Exploration ex = run(fischer.system, options);
    CHECK(ex.stop == StopReason::time_limit);
    CHECK_FALSE(ex.complete());
    CHECK(std::string(describe(ex.stop)) == "time limit reached");
  }
  SECTION("time, with a large level 0") {
    const auto ring = token_ring::build(7, 6);
    ExploreOptions options;
    options.limits.max_seconds = 1e-9;
    options.threads = 2;
    const Exploration ex = run(ring.system, options);
    CHECK(ex.stop == StopReason::time_limit);
    CHECK_FALSE(ex.complete());
  }
  SECTION("memory") {
    ExploreOptions options;
    options.limits.max_memory_bytes = 1;
    const Exploration ex = run(fischer.system, options);
    CHECK(ex.stop == StopReason::memory_limit);
    CHECK_FALSE(ex.complete());
    CHECK(std::string(describe(ex.stop)) == "memory limit reached");
  }
}

// Regression: vlayer-mc lemma-7.3 on 2x2 with --max-memory 16000 was killed by the kernel
// at 24 GB: buffers doubled between the checks of the limit. Now no buffer grows past it.
TEST_CASE("explore: the memory limit holds at every growth", "[checker][explorer][limits]") {
  const auto ring = token_ring::build(7, 6);
  ExploreHooks hooks;
  hooks.record_edges = true;
  for (unsigned threads : {1u, 2u}) {
    CAPTURE(threads);
    ExploreOptions options = with_threads(threads);
    const Exploration free = run(ring.system, options, hooks);
    REQUIRE(free.complete());
    REQUIRE(free.store.size() == 279936);
    CHECK(free.peak_memory_bytes >= free.memory_bytes());
    for (std::size_t share : {2u, 4u, 16u}) {
      CAPTURE(share);
      options.limits.max_memory_bytes = free.peak_memory_bytes / share;
      const Exploration ex = run(ring.system, options, hooks);
      CHECK(ex.stop == StopReason::memory_limit);
      CHECK(ex.peak_memory_bytes <= options.limits.max_memory_bytes);
      CHECK(ex.memory_bytes() <= options.limits.max_memory_bytes);
      CHECK(ex.parent.size() == ex.store.size());
    }
    if (threads == 1) { // one worker: what fitted without a limit fits within its peak
      options.limits.max_memory_bytes = free.peak_memory_bytes;
      const Exploration ex = run(ring.system, options, hooks);
      CHECK(ex.complete());
      CHECK(ex.peak_memory_bytes == free.peak_memory_bytes);
    }
  }
}

TEST_CASE("explore: hooks", "[checker][explorer][hooks]") {
  const tioa::Automaton d = diamond();
  const auto a = tioa::Variable<bool>{d.layout().find("a")->slot()};
  const auto b = tioa::Variable<bool>{d.layout().find("b")->slot()};

  SECTION("expand: states it refuses are stored but not expanded") {
    ExploreHooks hooks;
    hooks.expand = [&](const Word* s) { return !State(s, 0)[a]; };
    const Exploration ex = run(d, {}, hooks);
    CHECK(ex.store.size() == 4); // 00, 10 (kept), 01, then 11 from 01
    CHECK(ex.expanded == 2);     // 00 and 01
    CHECK(ex.edges == 3);
    CHECK(ex.stuck.empty()); // 11 was never expanded, so it is not reported stuck
    CHECK(ex.complete());
  }
  SECTION("target: stops at the first stored state where it holds") {
    ExploreHooks hooks;
    hooks.target = [&](const Word* s) { return State(s, 0)[a] && State(s, 0)[b]; };
    const Exploration ex = run(d, {}, hooks);
    REQUIRE(ex.found);
    CHECK(*ex.found == 3);
    CHECK(ex.stop == StopReason::found);
    CHECK(ex.complete());
    CHECK(std::string(describe(ex.stop)) == "found");
  }
  SECTION("target: a start state") {
    ExploreHooks hooks;
    hooks.target = [&](const Word* s) { return !State(s, 0)[a]; };
    const Exploration ex = run(d, {}, hooks);
    CHECK(ex.found == StateId{0});
    CHECK(ex.store.size() == 1);
    CHECK(ex.expanded == 0);
  }
  SECTION("target: the first of several in BFS order") {
    ExploreHooks hooks;
    hooks.target = [&](const Word* s) { return State(s, 0)[a] || State(s, 0)[b]; };
    const Exploration ex = run(d, {}, hooks);
    CHECK(ex.found == StateId{1}); // 10, reached by setA before 01 by setB
  }
  // The diamond is symmetric in a and b; ordering them (b ≤ a) keeps one state per class:
  // {00}, {10, 01}, {11}.
  const auto ordered = [&](Word* w) {
    State s(w, 0);
    if (!s[a] && s[b]) {
      s[a] = true;
      s[b] = false;
    }
  };
  SECTION("canonical: one state per class, successors and start states alike") {
    ExploreHooks hooks;
    hooks.canonical = ordered;
    const Exploration ex = run(d, with_threads(2), hooks);
    CHECK(ex.store.size() == 3);
    CHECK(ex.edges == 3); // 00 -setA-> 10, 00 -setB-> 10, 10 -setB-> 11
    for (StateId id = 0; id < ex.store.size(); ++id)
      CHECK_FALSE((!State(ex.store.state(id), 0)[a] && State(ex.store.state(id), 0)[b]));
    const Exploration anywhere = run(tioa::U(d), {}, hooks);
    CHECK(anywhere.start_states == 3); // the four valuations, three classes
    CHECK(anywhere.store.size() == 3);
  }
  SECTION("target never true: finished") {
    ExploreHooks hooks;
    hooks.target = [](const Word*) { return false; };
    const Exploration ex = run(d, {}, hooks);
    CHECK_FALSE(ex.found);
    CHECK(ex.stop == StopReason::finished);
    CHECK(ex.store.size() == 4);
  }
}

TEST_CASE("explore: a model error in an effect reaches the caller from any thread",
          "[checker][explorer][threads]") {
  // x in 0..5000 from anywhere (a level 0 big enough for the parallel path); inc writes
  // 5001 at x == 5000, outside the domain.
  tioa::Automaton a("overflow");
  const auto x = a.integer("x", 0, 5000, std::nullopt);
  a.internal("inc").eff([=](State& s, const Params&) { s[x] = s[x] + 1; });
  const tioa::Automaton u = tioa::U(a);
  for (unsigned threads : {1u, 4u}) {
    INFO(threads << " threads");
    CHECK_THROWS_MATCHES(
        run(u, with_threads(threads)), tioa::ModelError,
        Catch::Matchers::Message("value 5001 is outside the domain of variable 'x'"));
  }
}

TEST_CASE("explore: stuck states are reported in BFS order", "[checker][explorer]") {
  // x in 0..5 from anywhere; dec only from odd x: 0, 2 and 4 have nothing to do.
  tioa::Automaton a("odd");
  const auto x = a.integer("x", 0, 5, std::nullopt);
  a.internal("dec")
      .pre([=](const State& s, const Params&) { return s[x] % 2 == 1; })
      .eff([=](State& s, const Params&) { s[x] = s[x] - 1; });
  const Exploration ex = run(tioa::U(a));
  CHECK(ex.store.size() == 6);
  CHECK(ex.stuck == std::vector<StateId>{0, 2, 4});

  SECTION("none in the token ring: some process is always privileged") {
    CHECK(run(token_ring::build(4, 3).system).stuck.empty());
  }
}

TEST_CASE("explore: hooks as lambdas, as std::functions or none give the same exploration",
          "[checker][explorer][hooks]") {
  const auto fischer = fischer::build(5, 1, 2);
  const auto& a = fischer.system;
  const tioa::SuccessorGenerator generator(a);
  const auto locations = slots_named(a, "loc");
  auto waiting = [&](const Word* s) {
    int n = 0;
    for (const tioa::Slot& location : locations)
      n += State(s, 0).code(location) == 2 ? 1 : 0;
    return n;
  };
  auto expand = [&](const Word* s) { return waiting(s) < 3; };
  auto target = [&](const Word* s) { return waiting(s) == 4; };
  for (unsigned threads : {1u, 2u}) {
    INFO(threads << " threads");
    const ExploreOptions options = with_threads(threads);
    ExploreHooks functions;
    functions.expand = expand;
    functions.target = target;
    functions.record_edges = true;
    const Exploration one = explore(generator, a.start(), options, functions);
    const Exploration other = explore(generator, a.start(), options,
                                      hooks().with_expand(expand).with_target(target).with_edges());
    require_same(one, other);
    CHECK(edges_of(one) == edges_of(other));
    const Exploration none = explore(generator, a.start(), options);
    const Exploration empty = explore(generator, a.start(), options, ExploreHooks{});
    require_same(none, empty);
    CHECK(none.peak_memory_bytes == empty.peak_memory_bytes);
  }
}
