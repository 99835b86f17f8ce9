#include <vector>

#include "checker/checks.hpp"
#include "checker/closure_scan.hpp"
#include "checker/interrupt.hpp"
#include "checker/progress.hpp"
#include "tioa/start_set.hpp"

namespace checker {

namespace {

struct StopEnumeration {};

// The scan of one process (closure_scan.hpp).
ClosureScan scan_closure(const tioa::SuccessorGenerator& generator, const tioa::StateLayout& layout,
                         const StatePredicate& legal, const Limits& limits, Progress& progress) {
  const std::uint32_t words = generator.words();
  ClosureScan out;
  // L is found among every valuation, most of which may be outside it (token-ring N=9, K=9:
  // 585 members among 9^9): the limits are checked there too, not only at its members.
  // Sets out.limit when the run must stop (a signal, the time limit); true then.
  const auto out_of_limits = [&] {
    if (interrupted())
      out.limit = "interrupted";
    else if (limits.out_of_time(progress.elapsed()))
      out.limit = "time limit reached";
    return !out.limit.empty();
  };
  std::uint64_t tried = 0;
  const tioa::StartSet members = tioa::StartSet::satisfying(
      layout,
      [&](const tioa::State& s) {
        if ((++tried & 0xffff) == 0 && out_of_limits())
          throw StopEnumeration{};
        return legal(s);
      },
      "the legal set");
  std::vector<Word> state(words + 1, 0), scratch(words + 1, 0);
  const std::uint64_t max_states = limits.states_left();
  const bool exhausted = limits.states_exhausted();
  try {
    members.enumerate(state.data(), 0, [&] {
      if (exhausted || (max_states && out.members >= max_states)) {
        out.limit = "state limit reached";
        throw StopEnumeration{};
      }
      ++out.members;
      out.edges += generator.successors(
          state.data(), scratch.data(), [&](const Word* succ, const tioa::StepLabel&) {
            if (!out.bad_from && !legal(tioa::State(succ, 0))) {
              out.bad_from.emplace(state.begin(), state.begin() + words);
              out.bad_to.emplace(succ, succ + words);
            }
          });
      if (out.bad_from)
        throw StopEnumeration{};
      if ((out.members & 0xfff) == 0) {
        progress.update(out.members, 0, 0);
        if (out_of_limits())
          throw StopEnumeration{};
      }
    });
  } catch (const StopEnumeration&) {
  }
  return out;
}

} // namespace

PropertyResult check_legal_set(const Automaton& system, const StatePredicate& legal,
                               const ExploreOptions& options) {
  require_stored_states(options, "the legal-set check");
  const auto began = ScanClock::now();
  const tioa::SuccessorGenerator generator(system);
  Progress progress(options.progress, options.task.empty() ? "closure" : options.task);

  PropertyResult r;
  r.kind = "legal-set";
  r.store = to_string(options.store); // (asked for: the scan enumerates L and keeps no state)
  r.threads = 1;                      // one pass over the members of L, in enumeration order
  r.time_unit = generator.timed() ? "quanta" : "steps";
  ClosureScan scan;
  if (Collective* ranks = distributed()) {
    scan =
        scan_closure_distributed(generator, system.layout(), legal, options.limits, began, *ranks);
    r.ranks = static_cast<unsigned>(ranks->size());
  } else {
    scan = scan_closure(generator, system.layout(), legal, options.limits, progress);
  }
  r.states = scan.members;
  r.edges = scan.edges;
  options.limits.spend_states(r.states);
  r.seconds = progress.elapsed();
  if (scan.bad_from) {
    r.verdict = Verdict::violated;
    Trace trace;
    trace.steps.push_back({"", 0, *scan.bad_from});
    extend(generator, trace, scan.bad_to->data());
    r.trace = std::move(trace);
    r.trace_role = "counterexample";
    r.trace_kind = "closure-step";
    r.message = "a step leaves the legal set from one of its states";
  } else if (!scan.limit.empty()) {
    r.verdict = Verdict::incomplete;
    r.message = scan.limit + " after " + std::to_string(r.states) +
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
  if (!scan.bad_from && scan.limit.empty())
    r.coverage.of = r.states;
  return r;
}

} // namespace checker
