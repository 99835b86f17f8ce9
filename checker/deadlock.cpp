// Deadlocks and time-locks: a reachable state where no action (and, in a timed system,
// no tick) is possible. TIOA executions are expected to let time pass (seed 000 §3.1).

#include <optional>
#include <vector>

#include "checker/checks.hpp"
#include "checker/distributed_checks.hpp"
#include "checker/explorer.hpp"

namespace checker {

PropertyResult check_no_deadlock(const Automaton& system, const ExploreOptions& options,
                                 const StatePredicate& ended, const std::string& ended_name) {
  const tioa::SuccessorGenerator generator(system);
  std::optional<ZeroTimeReduction> reduction;
  if (options.por)
    reduction.emplace(generator, tioa::StatePredicate{}, true);
  if (Collective* ranks = distributed()) {
    PropertyResult r =
        check_no_deadlock_distributed(generator, system.start(), ended, ended_name, options,
                                      reduction ? &*reduction : nullptr, *ranks);
    if (reduction)
      reduction->note_time_passing(r.notes, r.reduced_states);
    return r;
  }
  const Exploration ex =
      explore(generator, system.start(), options, hooks(), reduction ? &*reduction : nullptr);
  PropertyResult r = result_of("deadlock", ex, generator);
  if (reduction)
    reduction->note_time_passing(r.notes, r.reduced_states);
  const char* what = generator.timed() ? "time-lock" : "deadlock";
  std::vector<StateId> stuck; // the stuck states that are not proper ends
  for (const StateId id : ex.stuck) {
    if (!ended) {
      stuck = ex.stuck;
      break;
    }
    // The fingerprint store keeps no states: the trace to it rebuilds the state.
    std::vector<Word> buffer; // (decoded on the compressed store)
    const std::vector<Word> state =
        ex.fingerprints()
            ? trace_to(generator, ex, id).steps.back().state
            : std::vector<Word>(ex.state(id, buffer), ex.state(id, buffer) + generator.words());
    if (!ended(tioa::State(state.data(), 0)))
      stuck.push_back(id);
  }
  if (stuck.size() < ex.stuck.size())
    r.notes.push_back(std::to_string(ex.stuck.size() - stuck.size()) +
                      " reachable states with no action are proper ends (" + ended_name +
                      "), not " + what + "s");
  if (!stuck.empty()) {
    r.verdict = Verdict::violated;
    r.trace = trace_to(generator, ex, stuck.front());
    r.trace_role = "counterexample";
    r.trace_kind = what;
    r.message = reachable_states(stuck.size(), ex) + " with no action" +
                (generator.timed() ? " and no tick" : "") + " (" + what + ")";
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, std::string("no ") + what + " in the states covered");
  } else {
    mark_holds(r, ex, std::string("no ") + what + " in " + reachable_states(r.states, ex));
  }
  return r;
}

} // namespace checker
