#pragma once
// vn-emulation along a written-out schedule, for findings that a search of their instance
// cannot reach or that a test should not wait minutes for (E4, E5 in
// models/vn_emulation/README.md): each step of the schedule must be enabled where it is
// taken; after it the run takes the first step the generator offers. The trace it builds
// is a trace of the model, checked with checker::replay by the tests.
#include <catch2/catch.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checker/trace.hpp"
#include "models/vn_emulation/emulation.hpp"
#include "models/vn_emulation/predicates.hpp"
#include "tioa/successors.hpp"

namespace vn_emulation_schedule {

struct Walk {
  checker::Trace trace;
  std::optional<std::string> failure; // replica_failure's, where it first holds
  int watched = 0; // states where time may pass and `watch` holds (no model bound met)
};

using Predicate = std::function<bool(const tioa::State&)>;

// From the first start state where `pick` holds (the first one when empty), along
// `schedule`, then the first step offered, until the replicas disagree, time reaches
// `until` or a model bound is met.
inline Walk walk(const vn_emulation::Emulation& e, const std::vector<std::string>& schedule,
                 std::uint64_t until, const Predicate& pick = {}, const Predicate& watch = {}) {
  const tioa::Automaton& a = e.automaton;
  const vn_emulation::Slots& slots = *e.slots;
  const tioa::SuccessorGenerator generator(a);
  std::vector<tioa::Word> words(a.words() + 1, 0), start;
  a.start().enumerate(words.data(), 0, [&] {
    if (start.empty() && (!pick || pick(tioa::State(words.data(), 0))))
      start.assign(words.begin(), words.end() - 1);
  });
  REQUIRE_FALSE(start.empty());
  Walk w;
  w.trace.steps.push_back({"", 0, start, {}});
  std::vector<tioa::Word> scratch(a.words() + 1, 0);
  for (std::size_t k = 0; !w.failure && w.trace.steps.back().time < until; ++k) {
    const checker::TraceStep& last = w.trace.steps.back();
    const bool scheduled = k < schedule.size();
    std::vector<tioa::Word> next;
    tioa::StepLabel taken;
    generator.successors(
        last.state.data(), scratch.data(), [&](const tioa::Word* s, const tioa::StepLabel& l) {
          if (next.empty() && (!scheduled || generator.describe(l) == schedule[k])) {
            next.assign(s, s + a.words());
            taken = l;
          }
        });
    INFO("step " << k + 1 << (scheduled ? ": " + schedule[k] : std::string()));
    REQUIRE_FALSE(next.empty());
    w.trace.steps.push_back({generator.describe(taken), last.time + generator.duration(taken), next,
                             checker::trace_action(generator, taken)});
    const tioa::State reached(w.trace.steps.back().state.data(), 0);
    if (slots.past_bound(reached))
      break;
    w.failure = vn_emulation::replica_failure(slots, reached);
    if (watch && !vn_emulation::urgent(slots, reached) && watch(reached))
      ++w.watched;
  }
  return w;
}

} // namespace vn_emulation_schedule
