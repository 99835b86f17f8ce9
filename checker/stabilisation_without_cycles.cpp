#include "checker/stabilisation_without_cycles.hpp"

#include <vector>

#include "checker/explorer.hpp"

namespace checker {

std::optional<PropertyResult> check_stabilisation_without_cycles(const Automaton& system,
                                                                 const StatePredicate& legal,
                                                                 const ExploreOptions& options) {
  if (!options.por || system.timed() || !system.progress_measure())
    return std::nullopt;
  const tioa::SuccessorGenerator generator(system);
  const ZeroTimeReduction reduction(generator, tioa::StatePredicate{});
  if (!reduction.can_reduce())
    return std::nullopt;
  require_stored_states(options, "the stabilisation check");
  const Exploration ex = explore(generator, system.start(), options, hooks(), &reduction);
  PropertyResult r = result_of("stabilisation", ex, generator);
  std::vector<StateId> ends_outside; // the stuck states outside L
  StateReader read(ex);
  for (const StateId id : ex.stuck)
    if (!legal(tioa::State(read(id), 0)))
      ends_outside.push_back(id);
  if (!ends_outside.empty()) {
    r.verdict = Verdict::violated;
    r.trace = trace_to(generator, ex, ends_outside.front());
    r.trace_role = "counterexample";
    r.trace_kind = "deadlock";
    r.message = "an execution gets stuck outside L (deadlock: no action)";
    return r;
  }
  if (!ex.complete()) {
    mark_incomplete(r, ex, "no execution found to stay outside L so far");
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "every execution ends in L: the graph has no cycle (its progress measure), and "
              "each of the " +
              std::to_string(ex.stuck.size()) + " states with no step in the reduced graph is in L";
  r.notes.push_back("worst time not measured: the partial-order reduction keeps every state "
                    "where an execution ends, not every execution (--por off measures it)");
  // A witness: an execution to the end found last (the deepest, in steps, of the search).
  if (!ex.stuck.empty()) {
    r.trace = trace_to(generator, ex, ex.stuck.back());
    r.trace_role = "witness";
    r.trace_kind = "end";
  }
  return r;
}

} // namespace checker
