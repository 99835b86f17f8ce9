#include <optional>

#include "checker/checks.hpp"
#include "checker/collective.hpp"
#include "checker/distributed_explorer.hpp"
#include "checker/explorer.hpp"
#include "checker/trace.hpp"

namespace checker {

namespace {

// check_invariant over the ranks of a distributed run: the same result as one process.
PropertyResult check_distributed(const tioa::SuccessorGenerator& generator,
                                 const tioa::StartSet& start, const StatePredicate& invariant,
                                 const ExploreOptions& options, bool por, Collective& ranks) {
  const DistributedExploration ex = explore_distributed(
      generator, start, options, [&](const tioa::State& s) { return !invariant(s); }, ranks);
  PropertyResult r;
  r.kind = "invariant";
  r.states = ex.states;
  r.edges = ex.edges;
  r.depth = ex.depth;
  r.seconds = ex.seconds;
  r.ranks = static_cast<unsigned>(ranks.size());
  r.por = por; // on, and (can_reduce() false) nothing to reduce: as one process says
  r.time_unit = generator.timed() ? "quanta" : "steps";
  r.coverage = {Starts::all, ex.start_states, ex.start_states, "the start states", ""};
  if (ex.found) {
    r.verdict = Verdict::violated;
    Trace trace;
    trace.steps.push_back({"", 0, ex.to_found.front()});
    for (std::size_t i = 1; i < ex.to_found.size(); ++i)
      extend(generator, trace, ex.to_found[i].data());
    r.trace = std::move(trace);
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = "a reachable state breaks the invariant; shortest trace: " +
                std::to_string(r.trace->length()) + " steps";
  } else if (!ex.complete()) {
    r.verdict = Verdict::incomplete;
    r.message = std::string(describe(ex.stop)) + " after " + std::to_string(ex.states) +
                " states to depth " + std::to_string(ex.depth) +
                ": no violation in the states covered";
  } else {
    r.verdict = Verdict::holds;
    r.message = "all " + std::to_string(r.states) + " reachable states satisfy it";
  }
  return r;
}

} // namespace

PropertyResult check_invariant(const Automaton& system, const StatePredicate& invariant,
                               const ExploreOptions& options) {
  const tioa::SuccessorGenerator generator(system);
  std::optional<ZeroTimeReduction> reduction;
  if (options.por)
    reduction.emplace(generator, invariant);
  if (Collective* ranks = distributed()) {
    if (options.store == StoreKind::fingerprint)
      throw NotDistributed("the fingerprint store does not run distributed yet: use the exact "
                           "store");
    if (reduction && reduction->can_reduce())
      throw NotDistributed("the partial-order reduction does not run distributed yet: use "
                           "--por off");
    return check_distributed(generator, system.start(), invariant, options, reduction.has_value(),
                             *ranks);
  }
  const Exploration ex =
      explore(generator, system.start(), options,
              hooks().with_target([&](const Word* s) { return !invariant(tioa::State(s, 0)); }),
              reduction ? &*reduction : nullptr);

  PropertyResult r = result_of("invariant", ex, generator);
  if (ex.found) {
    r.verdict = Verdict::violated;
    r.trace = trace_to(generator, ex, *ex.found);
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = std::string("a reachable state breaks the invariant; ") +
                (ex.reduced_states > 0 ? "trace (of the reduced graph): " : "shortest trace: ") +
                std::to_string(r.trace->length()) + " steps";
  } else if (!ex.complete()) {
    mark_incomplete(r, ex, "no violation in the states covered");
  } else {
    mark_holds(r, ex, "all " + reachable_states(r.states, ex) + " satisfy it");
  }
  return r;
}

} // namespace checker
