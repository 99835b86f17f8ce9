// Partial-order reduction of zero-time steps (checker/zero_time_reduction.hpp): fewer
// states, the same verdicts, real traces, and footprints that are checked.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "checker/checks.hpp"
#include "checker/zero_time_reduction.hpp"
#include "tests/checker/helpers.hpp"
#include "tioa/compose.hpp"

using namespace checker;
using checker_test::with_por;
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

// A sampler copies the time of its cycle (`now`, which only time changes) into `seen`
// (declared: seen := t, with t bound to now) and fires the value it saw once, when it saw
// its phase k; time cannot pass before it has sampled, nor while it owes the firing. Its
// listener takes the value (declared: last := v) and must acknowledge it (acks counts up
// to 2) before time passes. Within an instant whose time is not k, the sampler's write
// cannot enable the firing: the reduction sees it from the declared value.
Automaton sampler(int i, int period, int k) {
  Automaton a("s" + std::to_string(i));
  const auto now = a.integer("now", 0, period - 1, 0);
  const auto seen = a.integer("seen", 0, period - 1, period - 1);
  const auto fired = a.boolean("fired", false);
  a.internal("sample" + std::to_string(i), {{"t", 0, period - 1}})
      .pre([=](const State& s, const Params& m) { return s[seen] != s[now] && m[0] == s[now]; })
      .bind("t", now)
      .eff([=](State& s, const Params& m) { s[seen] = m[0]; })
      .footprint(
          [=](const Params& m, tioa::Footprint& f) { f.reads(now).reads(seen).sets(seen, m[0]); });
  a.output("fire" + std::to_string(i), {{"v", 0, period - 1}})
      .pre([=](const State& s, const Params& m) {
        return s[seen] == s[now] && s[seen] == k && !s[fired] && m[0] == s[seen];
      })
      .bind("v", seen)
      .eff([=](State& s, const Params&) { s[fired] = true; })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(seen).reads(now).reads(fired).sets(fired, true);
      });
  a.trajectories(
      [=](State& s) {
        s[now] = (s[now] + 1) % period;
        s[fired] = false;
      },
      [=](const State& s) { return s[seen] != s[now] || (s[seen] == k && !s[fired]); });
  return a;
}

Automaton listener(int i, int period) {
  Automaton a("l" + std::to_string(i));
  const auto last = a.integer("last", 0, period - 1, 0);
  const auto pending = a.boolean("pending", false);
  const auto acks = a.integer("acks", 0, 2, 0);
  a.input("fire" + std::to_string(i), {{"v", 0, period - 1}})
      .eff([=](State& s, const Params& m) {
        s[last] = m[0];
        s[pending] = true;
      })
      .footprint(
          [=](const Params& m, tioa::Footprint& f) { f.sets(last, m[0]).sets(pending, true); });
  a.internal("ack" + std::to_string(i))
      .pre([=](const State& s, const Params&) { return s[pending]; })
      .eff([=](State& s, const Params&) {
        s[pending] = false;
        s[acks] = std::min<int>(s[acks] + 1, 2);
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(pending).reads(acks).sets(pending, false).writes(acks);
      });
  a.trajectories([](State&) {}, [=](const State& s) { return s[pending]; });
  return a;
}

// A channel holds one message, posted at start and then `period` quanta after each
// delivery, urgently; the delivery (output deliver<i>) may happen from the post until the
// message's age is d (< period), urgently then. The age advances only while the message
// is pending, so delivering and ticking commute, as it declares. With `honest` false its
// clock stands still while a message is pending: they do not, though it says they do.
Automaton channel(int i, int period, int d, bool honest = true) {
  Automaton a("c" + std::to_string(i));
  const auto pending = a.boolean("pending", true);
  const auto age = a.integer("age", 0, d, 0);
  const auto clock = a.integer("clock", 0, period, 0);
  const std::string name = std::to_string(i);
  a.internal("post" + name)
      .pre([=](const State& s, const Params&) { return !s[pending] && s[clock] >= period; })
      .eff([=](State& s, const Params&) {
        s[pending] = true;
        s[age] = 0;
        s[clock] = 0;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(pending).reads(clock).sets(pending, true).sets(age, 0).sets(clock, 0);
      });
  a.output("deliver" + name)
      .pre([=](const State& s, const Params&) { return s[pending]; })
      .eff([=](State& s, const Params&) {
        s[pending] = false;
        s[age] = 0;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(pending).sets(pending, false).sets(age, 0);
      })
      .commutes_with_time();
  a.trajectories(
      [=](State& s) {
        if (honest || !s[pending])
          s[clock] = std::min<int>(s[clock] + 1, period);
        if (s[pending])
          s[age] = std::min<int>(s[age] + 1, d);
      },
      [=](const State& s) {
        return (s[pending] && s[age] >= d) || (!s[pending] && s[clock] >= period);
      });
  return a;
}

// Counts the deliveries of channel i up to `cap`; untimed, so time touches none of it.
Automaton inbox(int i, int cap) {
  Automaton a("i" + std::to_string(i));
  const auto got = a.integer("got", 0, cap, 0);
  a.input("deliver" + std::to_string(i))
      .eff([=](State& s, const Params&) { s[got] = std::min<int>(s[got] + 1, cap); })
      .footprint([=](const Params&, tioa::Footprint& f) { f.reads(got).writes(got); })
      .commutes_with_time();
  return a;
}

// Hears channel i (`heard`, which time does not read: the input commutes with a tick) and
// raises an alarm when it has heard it at local time 1 exactly: then time cannot pass and
// nothing can happen (a time-lock). The alarm reads the clock: it depends on time.
Automaton alarm(int i) {
  Automaton a("a" + std::to_string(i));
  const auto heard = a.boolean("heard", false);
  const auto clock = a.integer("clock", 0, 3, 0);
  const auto raised = a.boolean("raised", false);
  a.input("deliver" + std::to_string(i))
      .eff([=](State& s, const Params&) { s[heard] = true; })
      .footprint([=](const Params&, tioa::Footprint& f) { f.sets(heard, true); })
      .commutes_with_time();
  a.internal("raise" + std::to_string(i))
      .pre([=](const State& s, const Params&) { return s[heard] && s[clock] == 1 && !s[raised]; })
      .eff([=](State& s, const Params&) { s[raised] = true; })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(heard).reads(clock).reads(raised).sets(raised, true);
      });
  a.trajectories([=](State& s) { s[clock] = std::min<int>(s[clock] + 1, 3); },
                 [=](const State& s) { return s[raised]; });
  return a;
}

// Explores `a` with a reduction that does (or does not) reduce states where time passes.
checker::Exploration explore_reduced(const Automaton& a, bool time_passing) {
  const tioa::SuccessorGenerator generator(a);
  const ZeroTimeReduction reduction(generator, {}, time_passing);
  return checker::explore(generator, a.start(), checker::ExploreOptions{}, checker::hooks(),
                          &reduction);
}

tioa::StatePredicate count_below(const Automaton& a, int i, int value) {
  const auto count = tioa::find_variable<int>(a, "w" + std::to_string(i) + ".count");
  return [=](const State& s) { return s[count] < value; };
}

// The invariant is broken with and without the reduction, and the reduced trace replays
// to a state that breaks it.
void check_violated_both_ways(const Automaton& system, const tioa::StatePredicate& invariant) {
  const PropertyResult full = check_invariant(system, invariant, with_por(false));
  const PropertyResult reduced = check_invariant(system, invariant, with_por(true));
  CHECK(full.verdict == Verdict::violated);
  REQUIRE(reduced.verdict == Verdict::violated);
  std::string why;
  CHECK(replay(tioa::SuccessorGenerator(system), *reduced.trace, &why));
  CHECK(!invariant(State(reduced.trace->steps.back().state.data(), 0)));
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

TEST_CASE("with no footprint narrower than the whole state, nothing is reduced", "[por]") {
  // The workers of one automaton, with no footprint declared: every step may touch the
  // whole state, so the reduction cannot leave any out and the search is the full one.
  Automaton system("workers");
  const auto due = system.booleans("due", 3, true);
  for (int i = 0; i < 3; ++i)
    system.internal("work" + std::to_string(i))
        .pre([=](const State& s, const Params&) { return s[due[i]]; })
        .eff([=](State& s, const Params&) { s[due[i]] = false; });
  system.trajectories(
      [=](State& s) {
        for (int i = 0; i < 3; ++i)
          s[due[i]] = true;
      },
      [=](const State& s) { return s[due[0]] || s[due[1]] || s[due[2]]; });
  const tioa::SuccessorGenerator generator(system);
  CHECK_FALSE(ZeroTimeReduction(generator, {}).can_reduce());
  const tioa::StatePredicate anything = [](const State&) { return true; };
  const PropertyResult reduced = check_invariant(system, anything, with_por(true));
  CHECK(reduced.por);
  CHECK(reduced.states == 8); // every subset of the workers done
  CHECK(reduced.reduced_states == 0);
  // Composed, each worker's steps touch its own component only.
  CHECK(ZeroTimeReduction(tioa::SuccessorGenerator(workers(3, 1)), {}).can_reduce());
}

TEST_CASE("the reduction finds the invariant violations a full search finds", "[por]") {
  const Automaton system = workers(3, 3);
  for (int i = 0; i < 3; ++i)
    for (int value = 1; value <= 3; ++value) {
      INFO("w" << i << ".count < " << value);
      check_violated_both_ways(system, count_below(system, i, value));
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
    std::vector<std::string> counters; // variables an invariant may bound
    for (int i = 0; i < n; ++i) {
      const unsigned kind = random() % 6;
      if (kind == 0) {
        parts.push_back(racer(i, random() % 2 == 0));
      } else if (kind == 4) { // deliveries that commute with time
        const int d = 1 + static_cast<int>(random() % 2);
        parts.push_back(channel(i, d + 1 + static_cast<int>(random() % 2), d));
        parts.push_back(inbox(i, 1 + static_cast<int>(random() % 2)));
        counters.push_back("i" + std::to_string(i) + ".got");
      } else if (kind == 5) { // and a step that depends on when they happen
        parts.push_back(channel(i, 3, 2));
        parts.push_back(alarm(i));
      } else if (kind == 1) {
        const int period = 2 + static_cast<int>(random() % 3);
        parts.push_back(sampler(i, period, static_cast<int>(random() % period)));
        parts.push_back(listener(i, period));
        counters.push_back("l" + std::to_string(i) + ".acks");
      } else {
        parts.push_back(worker(i, 1 + static_cast<int>(random() % 3)));
        counters.push_back("w" + std::to_string(i) + ".count");
      }
    }
    const Automaton system = tioa::compose("random", parts);
    INFO("round " << round);
    const PropertyResult full = check_no_deadlock(system, with_por(false));
    const PropertyResult reduced = check_no_deadlock(system, with_por(true));
    CHECK(reduced.verdict == full.verdict);
    CHECK(reduced.states <= full.states);
    reduced_somewhere += reduced.states < full.states ? 1 : 0;
    // Every state where time can pass is kept.
    CHECK(checker_test::time_passing_states(system, true) ==
          checker_test::time_passing_states(system, false));
    if (!counters.empty()) {
      const auto counter = tioa::find_variable<int>(system, counters[random() % counters.size()]);
      const int value = 1 + static_cast<int>(random() % 3);
      const tioa::StatePredicate invariant = [=](const State& s) { return s[counter] < value; };
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

// `--por all`: the reduction in the stabilisation check too.
checker::ExploreOptions por_all() {
  checker::ExploreOptions options = with_por(true);
  options.por_stabilisation = true;
  return options;
}

// A legal set drawn for `system` over its counters: one bound, two joined by "and" or
// "or", or an equality (which executions leave again: L is not closed).
tioa::StatePredicate random_legal_set(const Automaton& system,
                                      const std::vector<std::string>& counters,
                                      std::mt19937& random, std::string& text) {
  auto pick = [&] {
    return tioa::find_variable<int>(system, counters[random() % counters.size()]);
  };
  const auto a = pick(), b = pick();
  const int u = static_cast<int>(random() % 3), v = static_cast<int>(random() % 3);
  switch (random() % 4) {
  case 0:
    text = "a >= u";
    return [=](const State& s) { return s[a] >= u; };
  case 1:
    text = "a >= u and b >= v";
    return [=](const State& s) { return s[a] >= u && s[b] >= v; };
  case 2:
    text = "a >= u or b < v";
    return [=](const State& s) { return s[a] >= u || s[b] < v; };
  default:
    text = "a = u";
    return [=](const State& s) { return s[a] == u; };
  }
}

TEST_CASE("random small systems: the same stabilisation verdicts and worst times with and "
          "without the reduction",
          "[por]") {
  std::mt19937 random(20261129);
  int reduced = 0, redone = 0, violated = 0;
  for (int round = 0; round < 60; ++round) {
    const int n = 2 + static_cast<int>(random() % 3);
    std::vector<Automaton> parts;
    std::vector<std::string> counters;
    for (int i = 0; i < n; ++i) {
      const unsigned kind = random() % 5;
      if (kind == 0) {
        parts.push_back(racer(i, random() % 2 == 0));
      } else if (kind == 1) {
        const int period = 2 + static_cast<int>(random() % 3);
        parts.push_back(sampler(i, period, static_cast<int>(random() % period)));
        parts.push_back(listener(i, period));
        counters.push_back("l" + std::to_string(i) + ".acks");
      } else if (kind == 2) {
        const int d = 1 + static_cast<int>(random() % 2);
        parts.push_back(channel(i, d + 1 + static_cast<int>(random() % 2), d));
        parts.push_back(inbox(i, 1 + static_cast<int>(random() % 2)));
        counters.push_back("i" + std::to_string(i) + ".got");
      } else {
        parts.push_back(worker(i, 1 + static_cast<int>(random() % 3)));
        counters.push_back("w" + std::to_string(i) + ".count");
      }
    }
    if (counters.empty())
      continue;
    const Automaton system = tioa::compose("random", parts);
    std::string text;
    const tioa::StatePredicate legal = random_legal_set(system, counters, random, text);
    INFO("round " << round << ", L: " << text);
    const PropertyResult full = check_stabilisation(system, legal, with_por(false));
    const PropertyResult on = check_stabilisation(system, legal, por_all());
    CHECK(on.verdict == full.verdict);
    CHECK(on.worst_time == full.worst_time);
    CHECK(on.states <= full.states);
    reduced += on.por && on.reduced_states > 0 ? 1 : 0;
    redone += !on.por ? 1 : 0;
    violated += on.verdict == Verdict::violated ? 1 : 0;
    if (on.trace) {
      std::string why;
      CHECK(replay(tioa::SuccessorGenerator(system), *on.trace, &why));
    }
  }
  // The sample exercises each way: reduced, redone in full, and violated.
  CHECK(reduced > 10);
  CHECK(redone > 0);
  CHECK(violated > 0);
}

TEST_CASE("stabilisation with the reduction keeps a state outside L that lasts no time", "[por]") {
  // In the first instant both workers work once. L = "w0 has worked or w1 has not": it
  // fails only between w1's step and w0's, so only the order "w1 first" leaves L, for no
  // time. That still counts (L is not closed: the check measures the last state outside
  // L), so the worst time is 1; a reduction that did not see L would take w0 first only.
  const Automaton system = workers(2, 1);
  const auto c0 = tioa::find_variable<int>(system, "w0.count");
  const auto c1 = tioa::find_variable<int>(system, "w1.count");
  const tioa::StatePredicate legal = [=](const State& s) { return s[c0] >= 1 || s[c1] < 1; };
  const PropertyResult full = check_stabilisation(system, legal, with_por(false));
  const PropertyResult on = check_stabilisation(system, legal, por_all());
  REQUIRE(full.verdict == Verdict::holds);
  CHECK(full.worst_time == 1);
  CHECK(on.verdict == Verdict::holds);
  CHECK(on.worst_time == 1);
}

TEST_CASE("stabilisation is checked again in full when the reduced graph has a time-lock in L",
          "[por]") {
  // After the racer's `b` time cannot pass again, in L: where the reduction left steps out,
  // a time-lock of the full graph could be missing from the reduced one (the argument in
  // checker/stabilisation.cpp), so the check runs again without it.
  const Automaton system = tioa::compose("racing", {worker(0, 2), worker(1, 2), racer(2, true)});
  const auto x = tioa::find_variable<int>(system, "r2.x");
  const tioa::StatePredicate legal = [=](const State& s) { return s[x] != 0; };
  const PropertyResult full = check_stabilisation(system, legal, with_por(false));
  const PropertyResult on = check_stabilisation(system, legal, por_all());
  CHECK(on.verdict == full.verdict);
  CHECK(on.worst_time == full.worst_time);
  CHECK_FALSE(on.por);
  CHECK(std::any_of(on.notes.begin(), on.notes.end(), [](const std::string& note) {
    return note.find("checked without the reduction") != std::string::npos;
  }));
}

TEST_CASE("stabilisation with the reduction: fewer states, the full graph's worst time", "[por]") {
  // Three workers that must each work once an instant, counting to 3: L = all at 3.
  const Automaton system = workers(3, 3);
  const auto c0 = tioa::find_variable<int>(system, "w0.count");
  const auto c2 = tioa::find_variable<int>(system, "w2.count");
  const tioa::StatePredicate legal = [=](const State& s) { return s[c0] == 3 && s[c2] == 3; };
  const PropertyResult full = check_stabilisation(system, legal, with_por(false));
  const PropertyResult on = check_stabilisation(system, legal, por_all());
  REQUIRE(full.verdict == Verdict::holds);
  CHECK(on.verdict == Verdict::holds);
  CHECK(on.worst_time == full.worst_time);
  CHECK(on.por);
  CHECK(on.states < full.states);
  std::string why;
  REQUIRE(on.trace);
  CHECK(replay(tioa::SuccessorGenerator(system), *on.trace, &why));
}

TEST_CASE("a sampler's declared value keeps its firing out of the set in other instants", "[por]") {
  // Two samplers with period 3 firing at phases 0 and 1, and their listeners. In full,
  // the two samples of an instant interleave; reduced, when neither sample can enable a
  // firing in this instant one order is enough.
  const Automaton system = tioa::compose(
      "samplers", {sampler(0, 3, 0), listener(0, 3), sampler(1, 3, 1), listener(1, 3)});
  const PropertyResult full = check_no_deadlock(system, with_por(false));
  const PropertyResult reduced = check_no_deadlock(system, with_por(true));
  CHECK(full.verdict == Verdict::holds);
  CHECK(reduced.verdict == Verdict::holds);
  CHECK(reduced.states < full.states);
  CHECK(checker_test::time_passing_states(system, true) ==
        checker_test::time_passing_states(system, false));
}

TEST_CASE("a writer whose declared value enables a dependent step stays in the set", "[por]") {
  // Each instant `write` sets x := 1, and `arm` arms (ready := true) the copy of x into y.
  // When the copy runs before the write, y = 0; after it, y = 1. The write and the copy
  // are dependent and the copy is not enabled at first: its enabling step (arm, whose
  // declared value does enable it) must be in the set, or the instant ending with y = 0
  // is lost.
  Automaton a("pair");
  const auto due_write = a.boolean("due_write", true);
  const auto x = a.integer("x", 0, 1, 0);
  const auto due_arm = a.boolean("due_arm", true);
  const auto ready = a.boolean("ready", false);
  const auto done = a.boolean("done", false);
  const auto y = a.integer("y", 0, 1, 0);
  a.internal("write")
      .pre([=](const State& s, const Params&) { return s[due_write]; })
      .eff([=](State& s, const Params&) {
        s[due_write] = false;
        s[x] = 1;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(due_write).sets(due_write, false).sets(x, 1);
      });
  a.internal("arm")
      .pre([=](const State& s, const Params&) { return s[due_arm]; })
      .eff([=](State& s, const Params&) {
        s[due_arm] = false;
        s[ready] = true;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(due_arm).sets(due_arm, false).sets(ready, true);
      });
  a.internal("copy")
      .pre([=](const State& s, const Params&) { return s[ready] && !s[done]; })
      .eff([=](State& s, const Params&) {
        s[done] = true;
        s[y] = s[x];
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(ready).reads(done).reads(x).sets(done, true).writes(y);
      });
  a.trajectories(
      [=](State& s) {
        s[due_write] = true;
        s[due_arm] = true;
        s[ready] = false;
        s[done] = false;
        s[x] = 0;
      },
      [=](const State& s) { return s[due_write] || s[due_arm] || (s[ready] && !s[done]); });
  const auto full = checker_test::time_passing_states(a, false);
  CHECK(checker_test::time_passing_states(a, true) == full);
  bool y0 = false, y1 = false;
  for (const auto& state : full) {
    y0 = y0 || State(state.data(), 0)[y] == 0;
    y1 = y1 || State(state.data(), 0)[y] == 1;
  }
  CHECK(y0);
  CHECK(y1);
}

TEST_CASE("a step that sets a value its footprint does not declare is a model error", "[por]") {
  Automaton liar("liar");
  const auto due = liar.boolean("due", true);
  const auto x = liar.integer("x", 0, 3, 0);
  liar.internal("lie")
      .pre([=](const State& s, const Params&) { return s[due]; })
      .eff([=](State& s, const Params&) {
        s[due] = false;
        s[x] = 2;
      })
      .footprint([=](const Params&, tioa::Footprint& f) { f.reads(due).writes(due).sets(x, 1); });
  liar.trajectories([=](State& s) { s[due] = true; }, [=](const State& s) { return s[due]; });
  const Automaton system = tioa::compose("system", {liar, worker(1, 1)});
  const tioa::StatePredicate anything = [](const State&) { return true; };
  CHECK_THROWS_WITH(check_invariant(system, anything, with_por(true)), Catch::Contains("'liar.x'"));
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

TEST_CASE("deliveries that commute with time are left for later where time can pass", "[por]") {
  const Automaton system = tioa::compose("mail", {channel(0, 3, 2), inbox(0, 2), channel(1, 3, 2),
                                                  inbox(1, 2), channel(2, 3, 2), inbox(2, 2)});
  {
    const tioa::SuccessorGenerator generator(system);
    CHECK(ZeroTimeReduction(generator, {}, true).reduces_time_passing());
    CHECK_FALSE(ZeroTimeReduction(generator, {}, false).reduces_time_passing());
  }
  const PropertyResult full = check_no_deadlock(system, with_por(false));
  const PropertyResult reduced = check_no_deadlock(system, with_por(true));
  CHECK(full.verdict == Verdict::holds);
  CHECK(reduced.verdict == Verdict::holds);
  // Each delivery may happen at age 0, 1 or 2: the full graph holds every mix of them;
  // reduced where time passes, they wait for their deadline.
  const checker::Exploration in_between_only = explore_reduced(system, false);
  const checker::Exploration both = explore_reduced(system, true);
  CHECK(both.store.size() < in_between_only.store.size());
  CHECK(in_between_only.store.size() <= full.states);
  CHECK(reduced.states == both.store.size());
  CHECK(std::any_of(reduced.notes.begin(), reduced.notes.end(), [](const std::string& n) {
    return n.find("states where time can pass") != std::string::npos;
  }));
  // The invariants on what was delivered: the same verdicts, real traces.
  for (int i = 0; i < 3; ++i)
    for (int value = 1; value <= 2; ++value) {
      const auto got = tioa::find_variable<int>(system, "i" + std::to_string(i) + ".got");
      INFO("i" << i << ".got < " << value);
      check_violated_both_ways(system, [=](const State& s) { return s[got] < value; });
    }
}

TEST_CASE("a timed step that reads what a delivery writes keeps the early delivery", "[por]") {
  // The alarm needs channel 0's delivery at time 1, before its deadline (2): leaving the
  // delivery for its deadline would miss the time-lock. The alarm depends on time, joins
  // the set with the tick, and its enabling set brings the delivery back in.
  const Automaton system =
      tioa::compose("watch", {channel(0, 3, 2), alarm(0), channel(1, 3, 2), inbox(1, 2)});
  const PropertyResult full = check_no_deadlock(system, with_por(false));
  const PropertyResult reduced = check_no_deadlock(system, with_por(true));
  CHECK(full.verdict == Verdict::violated);
  REQUIRE(reduced.verdict == Verdict::violated);
  const tioa::SuccessorGenerator generator(system);
  std::string why;
  CHECK(replay(generator, *reduced.trace, &why));
  CHECK(reduced.states < full.states);
}

TEST_CASE("a step that does not commute with time as it declares is a model error", "[por]") {
  const Automaton system =
      tioa::compose("mail", {channel(0, 3, 2, false), inbox(0, 2), channel(1, 3, 2), inbox(1, 2)});
  CHECK_THROWS_WITH(check_no_deadlock(system, with_por(true)),
                    Catch::Contains("declared to commute with time"));
  // Without the reduction the declaration is not used, and the check runs.
  CHECK(check_no_deadlock(system, with_por(false)).verdict == Verdict::holds);
}
