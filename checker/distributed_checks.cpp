#include "checker/distributed_checks.hpp"

#include <iomanip>
#include <sstream>

#include "checker/distributed_explorer.hpp"
#include "checker/fingerprint.hpp"
#include "checker/trace.hpp"

namespace checker {

namespace {

// The figures every result has (result_of() for one process).
PropertyResult figures_of(const std::string& kind, const DistributedExploration& ex,
                          const tioa::SuccessorGenerator& generator, bool por, Collective& ranks) {
  PropertyResult r;
  r.kind = kind;
  r.states = ex.states;
  r.edges = ex.edges;
  r.depth = ex.depth;
  r.seconds = ex.seconds;
  r.ranks = static_cast<unsigned>(ranks.size());
  r.threads = ex.threads;
  r.por = por;
  r.reduced_states = ex.reduced_states;
  if (ex.fingerprints) {
    r.store = "fingerprint";
    r.omission_probability = omission_probability(ex.states);
  }
  if (ex.compressed) {
    r.store = "compressed";
    if (ex.parts > 0) { // (a state of one word is its own key: no tree)
      std::ostringstream text;
      text << "compressed store: " << ex.states << " states held as keys into " << ex.parts
           << " parts in the ranks' trees (" << std::fixed << std::setprecision(1)
           << static_cast<double>(ex.store_bytes) / (1 << 20) << " MiB over the ranks)";
      r.notes.push_back(text.str());
    }
  }
  r.time_unit = generator.timed() ? "quanta" : "steps";
  r.coverage = {Starts::all, ex.start_states, ex.start_states, "the start states", ""};
  return r;
}

Trace trace_through(const tioa::SuccessorGenerator& generator,
                    const std::vector<std::vector<Word>>& states) {
  Trace trace;
  trace.steps.push_back({"", 0, states.front()});
  for (std::size_t i = 1; i < states.size(); ++i)
    extend(generator, trace, states[i].data());
  return trace;
}

// Holds, as mark_holds() says it: on the fingerprint store, up to hash collisions.
void mark_holds(PropertyResult& r, const DistributedExploration& ex, const std::string& message) {
  if (!ex.fingerprints) {
    r.verdict = Verdict::holds;
    r.message = message;
    return;
  }
  r.verdict = Verdict::incomplete;
  r.message = "holds up to hash collisions, omission probability ≤ " +
              format_probability(omission_probability(ex.states)) + ": " + message;
}

void mark_cut_short(PropertyResult& r, const DistributedExploration& ex,
                    const std::string& covered) {
  r.verdict = Verdict::incomplete;
  r.message = std::string(describe(ex.stop)) + " after " + std::to_string(ex.states) +
              " states to depth " + std::to_string(ex.depth) + ": " + covered;
  if (!ex.failure.empty())
    r.notes.push_back(ex.failure);
}

} // namespace

PropertyResult check_invariant_distributed(const tioa::SuccessorGenerator& generator,
                                           const tioa::StartSet& start,
                                           const tioa::StatePredicate& invariant,
                                           const ExploreOptions& options,
                                           const ZeroTimeReduction* reduction, Collective& ranks) {
  const DistributedExploration ex = explore_distributed(
      generator, start, options, [&](const tioa::State& s) { return !invariant(s); }, {}, reduction,
      ranks);
  PropertyResult r = figures_of("invariant", ex, generator, reduction != nullptr, ranks);
  if (ex.found) {
    r.verdict = Verdict::violated;
    r.trace = trace_through(generator, ex.to_found);
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = invariant_broken(r.trace->length(), ex.reduced_states);
  } else if (!ex.complete()) {
    mark_cut_short(r, ex, "no violation in the states covered");
  } else {
    mark_holds(r, ex, "all " + reachable_states(r.states, ex.reduced_states) + " satisfy it");
  }
  return r;
}

PropertyResult
check_no_deadlock_distributed(const tioa::SuccessorGenerator& generator,
                              const tioa::StartSet& start, const tioa::StatePredicate& ended,
                              const std::string& ended_name, const ExploreOptions& options,
                              const ZeroTimeReduction* reduction, Collective& ranks) {
  const DistributedExploration ex =
      explore_distributed(generator, start, options, {}, ended, reduction, ranks);
  PropertyResult r = figures_of("deadlock", ex, generator, reduction != nullptr, ranks);
  const char* what = generator.timed() ? "time-lock" : "deadlock";
  if (ex.ended > 0)
    r.notes.push_back(std::to_string(ex.ended) +
                      " reachable states with no action are proper ends (" + ended_name +
                      "), not " + what + "s");
  if (ex.first_stuck) {
    r.verdict = Verdict::violated;
    r.trace = trace_through(generator, ex.to_first_stuck);
    r.trace_role = "counterexample";
    r.trace_kind = what;
    r.message = reachable_states(ex.stuck, ex.reduced_states) + " with no action" +
                (generator.timed() ? " and no tick" : "") + " (" + what + ")";
  } else if (!ex.complete()) {
    mark_cut_short(r, ex, std::string("no ") + what + " in the states covered");
  } else {
    mark_holds(r, ex,
               std::string("no ") + what + " in " + reachable_states(r.states, ex.reduced_states));
  }
  return r;
}

} // namespace checker
