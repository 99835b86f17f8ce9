// The fingerprint store's two levels keep wide states packed (checker/level_states.hpp):
// a state comes back as it was put, whichever worker's arena holds it and after the level
// is renumbered; and a search over states of four words and more finds the exact store's
// ids, its first target and its first stuck state, with traces that replay.
#include <catch2/catch.hpp>

#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "checker/checks.hpp"
#include "checker/explorer.hpp"
#include "checker/fingerprint.hpp"
#include "checker/level_states.hpp"
#include "checker/trace.hpp"

using namespace checker;

namespace {

// Seven counters of 31 bits each (four words): each counts 0..3 and may then jump to a
// value with high bits; a state where every counter has jumped has no step.
struct WideCounters {
  tioa::Automaton a{"wide-counters"};
  std::vector<tioa::Variable<int>> x;
};

WideCounters wide_counters() {
  WideCounters w;
  tioa::Automaton& a = w.a;
  std::vector<tioa::Variable<int>>& x = w.x;
  for (int i = 0; i < 7; ++i)
    x.push_back(a.integer("x" + std::to_string(i), 0, (1 << 30) + 6, 0));
  const tioa::ParamRange which{"i", 0, 6};
  a.internal("count", {which})
      .pre([=](const tioa::State& s, const tioa::Params& p) { return s[x[p[0]]] < 3; })
      .eff([=](tioa::State& s, const tioa::Params& p) { s[x[p[0]]] = s[x[p[0]]] + 1; });
  a.internal("jump", {which})
      .pre([=](const tioa::State& s, const tioa::Params& p) { return s[x[p[0]]] == 3; })
      .eff([=](tioa::State& s, const tioa::Params& p) { s[x[p[0]]] = (1 << 30) + p[0]; });
  return w;
}

} // namespace

TEST_CASE("packed level states: what is put comes back, after renumbering too",
          "[checker][fingerprint]") {
  const std::uint32_t words = 70; // two mask words
  LevelStates levels(words);
  levels.set_writers(2);
  std::mt19937_64 random(7);
  std::vector<std::vector<Word>> states(300, std::vector<Word>(words));
  for (std::size_t k = 0; k < states.size(); ++k)
    for (std::uint32_t i = 0; i < words; ++i) // mostly as the first state, some words not
      states[k][i] = k == 0 || random() % 4 != 0 ? Word{i} * 977 : random();
  levels.reserve(1);
  levels.make_room(0, 1);
  levels.put(0, states[0].data(), 0); // the reference
  levels.next_level(1);
  levels.reserve(states.size());
  for (StateId id = 1; id < states.size(); ++id) {
    levels.make_room(id % 2, 1);
    levels.put(id, states[id].data(), id % 2);
  }
  std::vector<Word> out(words);
  for (StateId id = 1; id < states.size(); ++id) {
    levels.built(id, out.data());
    REQUIRE(out == states[id]);
  }
  // Renumbered backwards: the state that had id 1 + t gets id states.size() - 1 - t.
  std::vector<StateId> order(states.size() - 1);
  std::iota(order.rbegin(), order.rend(), StateId{1});
  levels.reorder(order, order.size());
  levels.next_level(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Word* state = levels.frontier(static_cast<StateId>(1 + i), out.data());
    REQUIRE(std::equal(state, state + words, states[order[i]].begin()));
  }
  CHECK(levels.bytes() > 0);
}

TEST_CASE("packed level states: a search over four-word states finds the exact store's ids, "
          "target and stuck state, for 1, 2 and 4 threads",
          "[checker][fingerprint][threads]") {
  const WideCounters counters = wide_counters();
  const tioa::Automaton& a = counters.a;
  const tioa::SuccessorGenerator generator(a);
  REQUIRE(generator.words() >= 4);
  ExploreOptions exact_options;
  exact_options.threads = 1;
  const Exploration exact = explore(generator, a.start(), exact_options, hooks());
  CHECK(exact.store.size() == 78'125); // 5^7
  for (unsigned threads : {1u, 2u, 4u}) {
    INFO(threads << " threads");
    ExploreOptions options;
    options.store = StoreKind::fingerprint;
    options.threads = threads;
    const Exploration fp = explore(generator, a.start(), options, hooks());
    REQUIRE(fp.store.size() == exact.store.size());
    CHECK(fp.parent == exact.parent);
    CHECK(fp.stuck == exact.stuck);
    bool same_ids = true;
    for (StateId id = 0; id < exact.store.size(); ++id)
      same_ids = same_ids &&
                 fp.store.state(id)[0] == fingerprint(exact.store.state(id), exact.store.words());
    CHECK(same_ids);
    REQUIRE(fp.first_stuck_state.size() == generator.words());
    CHECK(std::equal(fp.first_stuck_state.begin(), fp.first_stuck_state.end(),
                     exact.store.state(exact.stuck.front())));

    // A target (three counters at 3): its full state is kept, and its trace replays.
    const tioa::StatePredicate fewer_than_three = [&](const tioa::State& s) {
      int at_three = 0;
      for (const auto& x : counters.x)
        at_three += s[x] == 3;
      return at_three < 3;
    };
    const PropertyResult r = check_invariant(a, fewer_than_three, options);
    CHECK(r.verdict == Verdict::violated);
    REQUIRE(r.trace);
    CHECK(r.trace->length() == 9);
    std::string why;
    CHECK(replay(generator, *r.trace, &why));
    INFO(why);
    const PropertyResult stuck = check_no_deadlock(a, options);
    CHECK(stuck.verdict == Verdict::violated);
    REQUIRE(stuck.trace);
    CHECK(replay(generator, *stuck.trace, &why));
  }
}
