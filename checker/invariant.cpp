#include <optional>

#include "checker/checks.hpp"
#include "checker/distributed_checks.hpp"
#include "checker/explorer.hpp"

namespace checker {

PropertyResult check_invariant(const Automaton& system, const StatePredicate& invariant,
                               const ExploreOptions& options) {
  const tioa::SuccessorGenerator generator(system);
  std::optional<ZeroTimeReduction> reduction;
  if (options.por)
    reduction.emplace(generator, invariant, true);
  if (Collective* ranks = distributed()) {
    PropertyResult r = check_invariant_distributed(generator, system.start(), invariant, options,
                                                   reduction ? &*reduction : nullptr, *ranks);
    if (reduction)
      reduction->note_time_passing(r.notes, r.reduced_states);
    return r;
  }
  const Exploration ex =
      explore(generator, system.start(), options,
              hooks().with_target([&](const Word* s) { return !invariant(tioa::State(s, 0)); }),
              reduction ? &*reduction : nullptr);

  PropertyResult r = result_of("invariant", ex, generator);
  if (reduction)
    reduction->note_time_passing(r.notes, r.reduced_states);
  if (ex.found) {
    r.verdict = Verdict::violated;
    r.trace = trace_to(generator, ex, *ex.found);
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = invariant_broken(r.trace->length(), ex.reduced_states);
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, "no violation in the states covered");
  } else {
    mark_holds(r, ex, "all " + reachable_states(r.states, ex) + " satisfy it");
  }
  return r;
}

} // namespace checker
