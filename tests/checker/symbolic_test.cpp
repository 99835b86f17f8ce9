// The symbolic checks (checker/symbolic_*.hpp) against explicit exploration: the same
// reachable states, and the same worst stabilisation time from every start state.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>

#include "checker/checks.hpp"
#include "checker/symbolic_apart.hpp"
#include "checker/symbolic_stabilisation.hpp"
#include "helpers.hpp"
#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"
#include "tioa/compose.hpp"

using namespace checker;
using namespace checker_test;
namespace sym = checker::symbolic;

namespace {

tioa::StatePredicate variable_is(const tioa::Automaton& a, const std::string& name, int value) {
  const tioa::Slot slot = slot_of(a, name);
  const std::uint64_t code = static_cast<std::uint64_t>(value - a.layout().find(name)->lo);
  return [slot, code](const State& s) { return s.code(slot) == code; };
}

std::uint64_t explicit_count(const tioa::Automaton& a) {
  const tioa::SuccessorGenerator generator(a);
  const Exploration ex = explore(generator, a.start(), ExploreOptions{});
  REQUIRE(ex.complete());
  return ex.store.size();
}

double symbolic_count(const tioa::Automaton& a) {
  const sym::BddSession session(a.layout().bits());
  const sym::Space space(a);
  sym::BddSession::reorder_by_variables(a.layout());
  sym::LearningFigures figures;
  const sym::System system(space, figures);
  CHECK(figures.leaves > 0);
  return space.count(system.reach(sym::start_states(space, a.start())));
}

// The symbolic worst time from every start state of `a` (which must be U(A): every
// valuation), and check_stabilisation's.
struct BothWays {
  std::optional<std::uint64_t> symbolic, explicit_worst;
  double time_locked = 0, zero_time_forever = 0;
  Verdict verdict = Verdict::incomplete;
};

// With `settled` given, both count its states in L and expand none of them.
BothWays stabilise_both_ways(const tioa::Automaton& a, const tioa::StatePredicate& legal,
                             const tioa::StatePredicate& settled = {}) {
  BothWays both;
  const auto explicit_check = [&](const tioa::Automaton& from) {
    return settled ? check_stabilisation(from, legal, settled, {})
                   : check_stabilisation(from, legal, {});
  };
  {
    const sym::BddSession session(a.layout().bits());
    const sym::Space space(a);
    sym::LearningFigures figures;
    sym::System system(space, figures);
    sym::LearningFigures predicate;
    if (settled)
      system.set_settled(sym::learn_predicate(space, settled, predicate));
    const bdd in_legal = sym::learn_predicate(space, legal, predicate);
    const sym::StabilisationResult r = sym::stabilise(system, space.valid(), in_legal, 0);
    CHECK(r.start_states == space.count(space.valid()));
    both.symbolic = r.worst;
    both.time_locked = r.time_locked;
    both.zero_time_forever = r.zero_time_forever;
    const auto from = [&](const std::vector<tioa::Word>& start) {
      return tioa::Start(a, tioa::StartSet::listed(a.layout().bits(), a.words(), start, "picked"));
    };
    const bool stops_time = r.time_locked > 0 || r.zero_time_forever > 0;
    if (r.worst && *r.worst > 0 && !stops_time) {
      // The picked start state reaches the worst time, explored explicitly from it alone
      // (with a time-lock the explicit check reports that instead of a worst time).
      REQUIRE_FALSE(r.worst_start.empty());
      CHECK(explicit_check(from(r.worst_start)).worst_time == r.worst);
    }
    if (!r.worst && !stops_time) {
      // Outside L at every time: from the picked start state too.
      REQUIRE_FALSE(r.worst_start.empty());
      CHECK_FALSE(explicit_check(from(r.worst_start)).worst_time);
    }
    if (stops_time)
      REQUIRE_FALSE(r.time_lock_start.empty());
    if (r.time_locked > 0 && r.zero_time_forever == 0) {
      // The picked start state reaches a time-lock, which the explicit check reports as a
      // violation (it leaves endless zero-time runs out: they let no time pass).
      CHECK(explicit_check(from(r.time_lock_start)).verdict == Verdict::violated);
    }
  }
  const PropertyResult r = explicit_check(a);
  both.explicit_worst = r.worst_time;
  both.verdict = r.verdict;
  return both;
}

} // namespace

namespace {

// Two slots of values, delivered by a step bound to a slot's value (learned one point of
// its box at a time), to a receiver with a choice: the relations of a composition whose
// step reads different variables for different parameters.
tioa::Automaton bound_delivery() {
  tioa::Automaton sender("sender");
  const auto value = sender.integers("value", 2, 0, 3, std::nullopt);
  const auto pending = sender.booleans("pending", 2, std::nullopt);
  sender.internal("refill", {{"u", 0, 1}})
      .pre([=](const State& s, const Params& p) { return !s[pending[p[0]]]; })
      .choose([](const State&, const Params&) { return 4u; },
              [=](State& s, const Params& p, std::uint32_t c) {
                s[value[p[0]]] = static_cast<int>(c);
                s[pending[p[0]]] = true;
              });
  sender.output("deliver", {{"u", 0, 1}, {"x", 0, 3}})
      .pre([=](const State& s, const Params& p) {
        return s[pending[p[0]]] && s[value[p[0]]] == p[1];
      })
      .bind("x",
            [=](const State& s, const Params& p) -> std::optional<std::int32_t> {
              return s[value[p[0]]];
            })
      .eff([=](State& s, const Params& p) { s[pending[p[0]]] = false; });
  tioa::Automaton receiver("receiver");
  const auto got = receiver.integer("got", 0, 7, 0);
  receiver.input("deliver", {{"u", 0, 1}, {"x", 0, 3}})
      .choose([](const State&, const Params&) { return 2u; },
              [=](State& s, const Params& p, std::uint32_t c) {
                s[got] = (s[got] + p[1] + static_cast<int>(c)) % 8;
              });
  return tioa::compose("bound-delivery", {sender, receiver});
}

// Copies of values in three slots (1, empty, 2), delivered by a choose_where with one
// choice per slot, learned one choice at a time, to a receiver with a choice of its own.
// Reachable: the start; slot 0 delivered (got 1 or 2); slot 2 delivered (got 2 or 3);
// both (got 3, 4 or 5): 8 states. A delivery from a slot that does not hold its value
// (a choice not allowed) would reach more.
tioa::Automaton slot_delivery() {
  tioa::Automaton sender("sender");
  tioa::VariableArray<int> slot;
  const int initial[3] = {1, 0, 2};
  for (int i = 0; i < 3; ++i)
    slot.items.push_back(sender.integer("slot[" + std::to_string(i) + "]", 0, 3, initial[i]));
  sender.output("deliver", {{"x", 1, 3}})
      .choose_where(
          3,
          [=](const State& s, const Params& p, std::uint32_t c) {
            return s[slot[static_cast<int>(c)]] == p[0];
          },
          [=](State& s, const Params&, std::uint32_t c) { s[slot[static_cast<int>(c)]] = 0; });
  tioa::Automaton receiver("receiver");
  const auto got = receiver.integer("got", 0, 7, 0);
  receiver.input("deliver", {{"x", 1, 3}})
      .choose([](const State&, const Params&) { return 2u; },
              [=](State& s, const Params& p, std::uint32_t c) {
                s[got] = (s[got] + p[0] + static_cast<int>(c)) % 8;
              });
  return tioa::compose("slot-delivery", {sender, receiver});
}

} // namespace

TEST_CASE("symbolic: reachable states as explicit exploration counts them", "[checker][symbolic]") {
  {
    const tioa::Automaton a = bound_delivery();
    CHECK(explicit_count(a) > 100);
    CHECK(symbolic_count(a) == static_cast<double>(explicit_count(a)));
  }
  {
    const tioa::Automaton a = slot_delivery();
    CHECK(explicit_count(a) == 8);
    CHECK(symbolic_count(a) == static_cast<double>(explicit_count(a)));
  }
  for (int n : {2, 3, 4}) {
    const fischer::Fischer f = fischer::build(n, 1, 2);
    CHECK(symbolic_count(f.system) == static_cast<double>(explicit_count(f.system)));
  }
  for (auto [n, k] : {std::pair{3, 3}, std::pair{4, 5}}) {
    const token_ring::TokenRing ring = token_ring::build(n, k);
    CHECK(symbolic_count(ring.system) == static_cast<double>(explicit_count(ring.system)));
  }
}

TEST_CASE("symbolic: the worst time from every start state, as check_stabilisation measures it",
          "[checker][symbolic]") {
  SECTION("a timed countdown: top quanta") {
    const tioa::Automaton c = timed_countdown(4);
    const BothWays both = stabilise_both_ways(c, variable_is(c, "x", 0));
    CHECK(both.symbolic == 4u);
    CHECK(both.explicit_worst == 4u);
    CHECK(both.time_locked == 0);
    CHECK(both.zero_time_forever == 0);
  }
  SECTION("untimed: no ticks to count time in, refused") {
    const tioa::Automaton c = countdown(5, true);
    const sym::BddSession session(c.layout().bits());
    const sym::Space space(c);
    sym::LearningFigures figures;
    const sym::System system(space, figures);
    CHECK_THROWS_AS(sym::stabilise(system, space.valid(), space.valid(), 0), std::invalid_argument);
  }
  SECTION("a stop ends it, incomplete") {
    const tioa::Automaton c = timed_countdown(4);
    const sym::BddSession session(c.layout().bits());
    const sym::Space space(c);
    sym::LearningFigures figures;
    sym::System system(space, figures);
    system.set_stop([] { return true; });
    CHECK(sym::stabilise(system, space.valid(), space.valid(), 0).stopped);
  }
  SECTION("in a child process: the same result, and a stop ends it at once") {
    const tioa::Automaton c = timed_countdown(4);
    const sym::BddSession session(c.layout().bits());
    const sym::Space space(c);
    sym::LearningFigures figures;
    sym::System system(space, figures);
    sym::LearningFigures predicate;
    const bdd in_legal = sym::learn_predicate(space, variable_is(c, "x", 0), predicate);
    const sym::StabilisationResult here = sym::stabilise(system, space.valid(), in_legal, 0);
    const sym::StabilisationResult apart =
        sym::stabilise_apart(system, space.valid(), in_legal, 0, [] { return false; });
    CHECK_FALSE(apart.stopped);
    CHECK(apart.worst == here.worst);
    CHECK(apart.worst == 4u);
    CHECK(apart.start_states == here.start_states);
    CHECK(apart.reachable == here.reachable);
    CHECK(apart.layers == here.layers);
    CHECK(apart.worst_start == here.worst_start);
    REQUIRE_FALSE(apart.worst_start.empty());
    // A child that never ends (its stop is never asked: a loop in the child's copy of the
    // system) is killed when the parent's stop says so.
    system.set_stop([] {
      for (;;)
        ::pause();
      return false;
    });
    const auto began = std::chrono::steady_clock::now();
    const sym::StabilisationResult killed =
        sym::stabilise_apart(system, space.valid(), in_legal, 0, [&] {
          return std::chrono::steady_clock::now() - began > std::chrono::milliseconds(300);
        });
    CHECK(killed.stopped);
    CHECK(killed.start_states == here.start_states);
    system.set_stop({});
  }
  SECTION("every group of every fixpoint round is reported, with its stage") {
    const tioa::Automaton c = timed_countdown(4);
    const sym::BddSession session(c.layout().bits());
    const sym::Space space(c);
    sym::LearningFigures figures;
    sym::System system(space, figures);
    std::vector<std::string> reports;
    system.set_progress([&](const std::string& status) { reports.push_back(status); });
    sym::LearningFigures predicate;
    const bdd in_legal = sym::learn_predicate(space, variable_is(c, "x", 0), predicate);
    const auto r = sym::stabilise(system, space.valid(), in_legal, 0);
    CHECK(r.worst == 4u);
    REQUIRE_FALSE(reports.empty());
    CHECK(reports.front().rfind("time layer 0: zero-time closure, round 1, ", 0) == 0);
    CHECK(reports.front().find(" BDD nodes") != std::string::npos);
    const auto said = [&](const std::string& part) {
      return std::any_of(reports.begin(), reports.end(),
                         [&](const std::string& s) { return s.find(part) != std::string::npos; });
    };
    CHECK(said("everything reachable: reach, round 1, tick, "));
    CHECK(said("time layer 4: staying inside, round 1, tick, "));
  }
  SECTION("learning reports its cubes, and a stop ends it") {
    // A guard that reads 13 booleans: 8 192 cubes, reported every 4 096.
    tioa::Automaton c("parity");
    const auto b = c.booleans("b", 13, std::nullopt);
    c.internal("flip")
        .pre([=](const State& s, const Params&) {
          bool odd = false;
          for (int i = 0; i < 13; ++i)
            odd = odd != s[b[i]];
          return odd;
        })
        .eff([=](State& s, const Params&) { s[b[0]] = !s[b[0]]; });
    const sym::BddSession session(c.layout().bits());
    const sym::Space space(c);
    sym::LearningFigures figures;
    std::vector<std::string> reports;
    const sym::System system(space, figures, {},
                             [&](const std::string& status) { reports.push_back(status); });
    CHECK(std::find(reports.begin(), reports.end(), "learning flip, 4096 cubes") != reports.end());
    CHECK(std::find(reports.begin(), reports.end(), "learning flip, 8192 cubes") != reports.end());
    sym::LearningFigures again;
    CHECK_THROWS_AS(sym::System(space, again, [] { return true; }), sym::Stopped);
  }
  SECTION("a zero-time cycle outside L") {
    const tioa::Automaton c = timed_countdown(3, true);
    const BothWays both = stabilise_both_ways(c, variable_is(c, "x", 0));
    CHECK(both.zero_time_forever > 0);
  }
  SECTION("time-locks: a stuck state, and states whose zero-time steps all lead to it") {
    // Time stops at x = 1; from there `drop` goes to x = 0 only when b holds: with b false
    // the state is stuck, a time-lock. The short way (no stuck state) must not apply.
    tioa::Automaton c("locking-countdown");
    const auto x = c.integer("x", 0, 3, std::nullopt);
    const auto b = c.boolean("b", std::nullopt);
    c.internal("drop")
        .pre([=](const State& s, const Params&) { return s[x] == 1 && s[b]; })
        .eff([=](State& s, const Params&) { s[x] = 0; });
    c.trajectories(
        [=](State& s) {
          if (s[x] > 0)
            s[x] = s[x] - 1;
        },
        [=](const State& s) { return s[x] == 1; });
    const tioa::Automaton u = tioa::U(c);
    const BothWays both = stabilise_both_ways(u, variable_is(u, "x", 0));
    CHECK(both.time_locked == 1); // x = 1, b false
    CHECK(both.zero_time_forever == 0);
    CHECK(both.verdict == Verdict::violated); // the explicit check finds the time-lock
  }
  SECTION("settled states count as in L from the time they are entered") {
    const tioa::Automaton c = timed_countdown(6);
    const BothWays both = stabilise_both_ways(c, variable_is(c, "x", 0), variable_is(c, "x", 2));
    CHECK(both.symbolic == 4u);
    CHECK(both.explicit_worst == 4u);
  }
  SECTION("Fischer from every valuation, with settled states") {
    const fischer::Fischer f = fischer::build(3, 1, 2);
    const tioa::Automaton u = tioa::U(f.system);
    const BothWays both = stabilise_both_ways(u, f.at_most_one_in_cs, variable_is(u, "loc[1]", 0));
    if (both.explicit_worst)
      CHECK(both.symbolic == both.explicit_worst);
    else
      CHECK_FALSE(both.symbolic);
  }
  SECTION("Fischer from every valuation: mutual exclusion") {
    const fischer::Fischer f = fischer::build(2, 1, 2);
    const tioa::Automaton u = tioa::U(f.system);
    const BothWays both = stabilise_both_ways(u, f.at_most_one_in_cs);
    INFO("explicit verdict " << static_cast<int>(both.verdict));
    if (both.explicit_worst)
      CHECK(both.symbolic == both.explicit_worst);
    else
      CHECK_FALSE(both.symbolic);
  }
}

namespace {

// Whether the symbolic System of `a` proves its zero-time steps free of cycles.
bool acyclic_proved(const tioa::Automaton& a) {
  const sym::BddSession session(a.layout().bits());
  const sym::Space space(a);
  sym::LearningFigures figures;
  const sym::System system(space, figures);
  return system.zero_time_acyclic();
}

} // namespace

TEST_CASE("symbolic: zero-time steps proved free of cycles, or left to the fixpoint",
          "[checker][symbolic]") {
  SECTION("a real cycle (flip toggles b while x > 0): not proved") {
    CHECK_FALSE(acyclic_proved(timed_countdown(3, true)));
  }
  SECTION("a counter that zero-time steps only lower: proved by the monotone rule") {
    tioa::Automaton c("draining");
    const auto y = c.integer("y", 0, 3, std::nullopt);
    c.internal("drain")
        .pre([=](const State& s, const Params&) { return s[y] > 0; })
        .eff([=](State& s, const Params&) { s[y] = s[y] - 1; });
    c.trajectories([](State&) {});
    CHECK(acyclic_proved(tioa::U(c)));
  }
  SECTION("v set to a wanted value, up or down, only while it differs: the dead-end rule") {
    tioa::Automaton c("settling");
    const auto want = c.integer("want", 0, 3, std::nullopt);
    const auto v = c.integer("v", 0, 3, std::nullopt);
    c.internal("set", {{"to", 0, 3}})
        .pre([=](const State& s, const Params& p) { return s[v] != s[want] && p[0] == s[want]; })
        .eff([=](State& s, const Params& p) { s[v] = p[0]; });
    c.trajectories([=](State& s) { s[want] = (s[want] + 1) % 4; });
    CHECK(acyclic_proved(tioa::U(c)));
  }
  SECTION("two steps that undo each other: a real cycle, not proved") {
    tioa::Automaton c("swapping");
    const auto p = c.boolean("p", std::nullopt);
    const auto q = c.boolean("q", std::nullopt);
    c.internal("there")
        .pre([=](const State& s, const Params&) { return s[p] && !s[q]; })
        .eff([=](State& s, const Params&) {
          s[p] = false;
          s[q] = true;
        });
    c.internal("back")
        .pre([=](const State& s, const Params&) { return !s[p] && s[q]; })
        .eff([=](State& s, const Params&) {
          s[p] = true;
          s[q] = false;
        });
    c.trajectories([](State&) {});
    const tioa::Automaton u = tioa::U(c);
    CHECK_FALSE(acyclic_proved(u));
    CHECK(stabilise_both_ways(u, [](const State&) { return true; }).zero_time_forever == 2);
  }
}
