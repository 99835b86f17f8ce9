// Partial-order reduction of zero-time steps (checker/zero_time_reduction.hpp): fewer
// states, the same verdicts, real traces, and footprints that are checked.
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "checker/checks.hpp"
#include "tioa/compose.hpp"

using namespace checker;
using tioa::Automaton;
using tioa::Params;
using tioa::State;

namespace {

// A worker must work once in every instant (time cannot pass while it is due) and counts
// its work up to `cap`. Workers are independent: n of them interleave in 2^n ways.
Automaton worker(int i, int cap) {
  Automaton a("w" + std::to_string(i));
  const auto due = a.boolean("due", true);
  const auto count = a.integer("count", 0, cap, 0);
  a.internal("work" + std::to_string(i))
      .pre([=](const State& s, const Params&) { return s[due]; })
      .eff([=](State& s, const Params&) {
        s[due] = false;
        s[count] = std::min<int>(s[count] + 1, cap);
      });
  a.trajectories([=](State& s) { s[due] = true; }, [=](const State& s) { return s[due]; });
  return a;
}

Automaton workers(int n, int cap) {
  std::vector<Automaton> parts;
  for (int i = 0; i < n; ++i)
    parts.push_back(worker(i, cap));
  return tioa::compose("workers", parts);
}

// Takes `a` or `b` at once; after `b` time cannot pass (when `locks`) or it may (else).
Automaton racer(int i, bool locks) {
  Automaton a("r" + std::to_string(i));
  const auto x = a.integer("x", 0, 2, 0);
  const std::string name = std::to_string(i);
  a.internal("a" + name)
      .pre([=](const State& s, const Params&) { return s[x] == 0; })
      .eff([=](State& s, const Params&) { s[x] = 1; });
  a.internal("b" + name)
      .pre([=](const State& s, const Params&) { return s[x] == 0; })
      .eff([=](State& s, const Params&) { s[x] = 2; });
  a.trajectories([](State&) {}, [=](const State& s) { return s[x] == 0 || (locks && s[x] == 2); });
  return a;
}

ExploreOptions with_por(bool on) {
  ExploreOptions options;
  options.por = on;
  return options;
}

tioa::StatePredicate count_below(const Automaton& a, int i, int value) {
  const auto count = tioa::find_variable<int>(a, "w" + std::to_string(i) + ".count");
  return [=](const State& s) { return s[count] < value; };
}

} // namespace

TEST_CASE("independent zero-time steps are explored in one order", "[por]") {
  const Automaton system = workers(4, 2);
  const tioa::StatePredicate anything = [](const State&) { return true; };
  const PropertyResult full = check_invariant(system, anything, with_por(false));
  const PropertyResult reduced = check_invariant(system, anything, with_por(true));
  CHECK(full.verdict == Verdict::holds);
  CHECK(reduced.verdict == Verdict::holds);
  CHECK_FALSE(full.por);
  CHECK(reduced.por);
  // Three instants (counts 0 -> 1, 1 -> 2, 2 -> 2): in full each holds the 2^4 subsets of
  // the workers that are done, in the reduced graph one chain of 5 states; the last two
  // instants end in the same state (all done, counts 2).
  CHECK(full.states == 16 * 3 - 1);
  CHECK(reduced.states == 5 * 3 - 1);
  CHECK(reduced.reduced_states > 0);
}

TEST_CASE("the reduction finds the invariant violations a full search finds", "[por]") {
  const Automaton system = workers(3, 3);
  for (int i = 0; i < 3; ++i)
    for (int value = 1; value <= 3; ++value) {
      const auto invariant = count_below(system, i, value);
      const PropertyResult full = check_invariant(system, invariant, with_por(false));
      const PropertyResult reduced = check_invariant(system, invariant, with_por(true));
      INFO("w" << i << ".count < " << value);
      CHECK(full.verdict == Verdict::violated);
      REQUIRE(reduced.verdict == Verdict::violated);
      const tioa::SuccessorGenerator generator(system);
      std::string why;
      CHECK(replay(generator, *reduced.trace, &why));
      CHECK(!invariant(State(reduced.trace->steps.back().state.data(), 0)));
    }
}

TEST_CASE("the reduction keeps time-locks that depend on the order of zero-time steps", "[por]") {
  // `racer` takes `a` or `b`; after `b` it is stuck where time cannot pass. Two workers
  // interleave with it.
  Automaton racer("racer");
  const auto x = racer.integer("x", 0, 2, 0);
  racer.internal("a")
      .pre([=](const State& s, const Params&) { return s[x] == 0; })
      .eff([=](State& s, const Params&) { s[x] = 1; });
  racer.internal("b")
      .pre([=](const State& s, const Params&) { return s[x] == 0; })
      .eff([=](State& s, const Params&) { s[x] = 2; });
  racer.trajectories([](State&) {}, [=](const State& s) { return s[x] != 1; });
  const Automaton system = tioa::compose("race", {worker(0, 1), racer, worker(1, 1)});
  const PropertyResult full = check_no_deadlock(system, with_por(false));
  const PropertyResult reduced = check_no_deadlock(system, with_por(true));
  CHECK(full.verdict == Verdict::violated);
  CHECK(reduced.verdict == Verdict::violated);
  CHECK(reduced.states < full.states);
}

TEST_CASE("a step that writes outside its declared footprint is a model error", "[por]") {
  Automaton liar("liar");
  const auto due = liar.boolean("due", true);
  const auto other = liar.boolean("other", false);
  liar.internal("lie")
      .pre([=](const State& s, const Params&) { return s[due]; })
      .eff([=](State& s, const Params&) {
        s[due] = false;
        s[other] = true;
      })
      .footprint([=](const Params&, tioa::Footprint& f) { f.reads(due).writes(due); });
  liar.trajectories([=](State& s) { s[due] = true; }, [=](const State& s) { return s[due]; });
  const Automaton system = tioa::compose("system", {liar, worker(1, 1)});
  const tioa::StatePredicate anything = [](const State&) { return true; };
  CHECK_THROWS_WITH(check_invariant(system, anything, with_por(true)),
                    Catch::Contains("wrote 'liar.other'"));
}

TEST_CASE("random small systems: the same verdicts with and without the reduction", "[por]") {
  std::mt19937 random(20261124);
  int reduced_somewhere = 0;
  for (int round = 0; round < 40; ++round) {
    const int n = 2 + static_cast<int>(random() % 3);
    std::vector<Automaton> parts;
    std::vector<int> workers_at;
    for (int i = 0; i < n; ++i) {
      if (random() % 3 == 0) {
        parts.push_back(racer(i, random() % 2 == 0));
      } else {
        parts.push_back(worker(i, 1 + static_cast<int>(random() % 3)));
        workers_at.push_back(i);
      }
    }
    const Automaton system = tioa::compose("random", parts);
    INFO("round " << round);
    const PropertyResult full = check_no_deadlock(system, with_por(false));
    const PropertyResult reduced = check_no_deadlock(system, with_por(true));
    CHECK(reduced.verdict == full.verdict);
    CHECK(reduced.states <= full.states);
    reduced_somewhere += reduced.states < full.states ? 1 : 0;
    if (!workers_at.empty()) {
      const int i = workers_at[random() % workers_at.size()];
      const int value = 1 + static_cast<int>(random() % 3);
      const auto invariant = count_below(system, i, value);
      const PropertyResult full_inv = check_invariant(system, invariant, with_por(false));
      const PropertyResult reduced_inv = check_invariant(system, invariant, with_por(true));
      CHECK(reduced_inv.verdict == full_inv.verdict);
      if (reduced_inv.trace) {
        const tioa::SuccessorGenerator generator(system);
        std::string why;
        CHECK(replay(generator, *reduced_inv.trace, &why));
      }
    }
  }
  CHECK(reduced_somewhere > 20);
}

TEST_CASE("a step with no choice gives no successor, reduced or not", "[por]") {
  // `idle` always offers a step with no choice and never lets time pass: once the worker
  // is done, nothing can happen (a time-lock), with and without the reduction.
  Automaton idle("idle");
  idle.boolean("b", false);
  idle.internal("nothing").choose(0, [](State&, const Params&, std::uint32_t) {});
  idle.trajectories([](State&) {}, [](const State&) { return true; });
  const Automaton system = tioa::compose("stuck", {idle, worker(0, 1)});
  const PropertyResult full = check_no_deadlock(system, with_por(false));
  const PropertyResult reduced = check_no_deadlock(system, with_por(true));
  CHECK(full.verdict == Verdict::violated);
  CHECK(reduced.verdict == Verdict::violated);
  CHECK(reduced.states == full.states);
}
