// Deadlocks and time-locks: a reachable state where no action (and, in a timed system,
// no tick) is possible. TIOA executions are expected to let time pass (seed 000 §3.1).

#include <optional>

#include "checker/checks.hpp"
#include "checker/explorer.hpp"

namespace checker {

PropertyResult check_no_deadlock(const Automaton& system, const ExploreOptions& options) {
  const tioa::SuccessorGenerator generator(system);
  std::optional<ZeroTimeReduction> reduction;
  if (options.por && generator.timed())
    reduction.emplace(generator, tioa::StatePredicate{});
  const Exploration ex =
      explore(generator, system.start(), options, hooks(), reduction ? &*reduction : nullptr);
  PropertyResult r = result_of("deadlock", ex, generator);
  const char* what = generator.timed() ? "time-lock" : "deadlock";
  if (!ex.stuck.empty()) {
    r.verdict = Verdict::violated;
    r.trace = trace_to(generator, ex, ex.stuck.front());
    r.trace_role = "counterexample";
    r.trace_kind = what;
    r.message = reachable_states(ex.stuck.size(), ex) + " with no action" +
                (generator.timed() ? " and no tick" : "") + " (" + what + ")";
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, std::string("no ") + what + " in the states covered");
  } else {
    mark_holds(r, ex, std::string("no ") + what + " in " + reachable_states(r.states, ex));
  }
  return r;
}

} // namespace checker
