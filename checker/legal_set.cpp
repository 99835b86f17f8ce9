#include <vector>

#include "checker/checks.hpp"
#include "checker/interrupt.hpp"
#include "checker/progress.hpp"
#include "tioa/start_set.hpp"

namespace checker {

namespace {
struct StopEnumeration {};
} // namespace

PropertyResult check_legal_set(const Automaton& system, const StatePredicate& legal,
                               const ExploreOptions& options) {
  require_exact_store(options, "the legal-set check");
  const tioa::SuccessorGenerator generator(system);
  const std::uint32_t words = generator.words();
  Progress progress(options.progress, options.task.empty() ? "closure" : options.task);
  // L is found among every valuation, most of which may be outside it (token-ring N=9, K=9:
  // 585 members among 9^9): the limits are checked there too, not only at its members.
  std::string limit;
  // Sets `limit` when the run must stop (a signal, the time limit); true then.
  const auto out_of_limits = [&] {
    if (interrupted())
      limit = "interrupted";
    else if (options.limits.out_of_time(progress.elapsed()))
      limit = "time limit reached";
    return !limit.empty();
  };
  std::uint64_t tried = 0;
  const tioa::StartSet members = tioa::StartSet::satisfying(
      system.layout(),
      [&](const tioa::State& s) {
        if ((++tried & 0xffff) == 0 && out_of_limits())
          throw StopEnumeration{};
        return legal(s);
      },
      "the legal set");

  PropertyResult r;
  r.kind = "legal-set";
  r.threads = 1; // one pass over the members of L, in enumeration order
  r.time_unit = generator.timed() ? "quanta" : "steps";
  std::vector<Word> state(words + 1, 0), scratch(words + 1, 0);
  std::optional<std::vector<Word>> bad_from, bad_to;
  const std::uint64_t max_states = options.limits.states_left();
  const bool exhausted = options.limits.states_exhausted();
  try {
    members.enumerate(state.data(), 0, [&] {
      if (exhausted || (max_states && r.states >= max_states)) {
        limit = "state limit reached";
        throw StopEnumeration{};
      }
      ++r.states;
      r.edges += generator.successors(state.data(), scratch.data(),
                                      [&](const Word* succ, const tioa::StepLabel&) {
                                        if (!bad_from && !legal(tioa::State(succ, 0))) {
                                          bad_from.emplace(state.begin(), state.begin() + words);
                                          bad_to.emplace(succ, succ + words);
                                        }
                                      });
      if (bad_from)
        throw StopEnumeration{};
      if ((r.states & 0xfff) == 0) {
        progress.update(r.states, 0, 0);
        if (out_of_limits())
          throw StopEnumeration{};
      }
    });
  } catch (const StopEnumeration&) {
  }
  options.limits.spend_states(r.states);
  r.seconds = progress.elapsed();
  if (bad_from) {
    r.verdict = Verdict::violated;
    Trace trace;
    trace.steps.push_back({"", 0, *bad_from});
    extend(generator, trace, bad_to->data());
    r.trace = std::move(trace);
    r.trace_role = "counterexample";
    r.trace_kind = "closure-step";
    r.message = "a step leaves the legal set from one of its states";
  } else if (!limit.empty()) {
    r.verdict = Verdict::incomplete;
    r.message = limit + " after " + std::to_string(r.states) +
                " states of the legal set, all closed so far";
  } else if (r.states == 0) {
    r.verdict = Verdict::violated;
    r.message = "the legal set is empty (seed 000 §3.1 requires a nonempty set)";
  } else {
    r.verdict = Verdict::holds;
    r.message =
        "closed: every step from each of its " + std::to_string(r.states) + " states stays in it";
  }
  // Every member of L is enumerated, so the closure covers all of them (how many is known
  // when the enumeration finished).
  r.coverage = {Starts::all, r.states, std::nullopt, "the legal set", ""};
  if (!bad_from && limit.empty())
    r.coverage.of = r.states;
  return r;
}

} // namespace checker
