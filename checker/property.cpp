#include "checker/property.hpp"

#include <stdexcept>

#include "checker/memory_budget.hpp"

namespace checker {

const char* to_string(PropertyKind kind) {
  switch (kind) {
  case PropertyKind::invariant:
    return "invariant";
  case PropertyKind::legal_set:
    return "legal-set";
  case PropertyKind::stabilisation:
    return "stabilisation";
  case PropertyKind::transitivity:
    return "transitivity";
  case PropertyKind::custom:
    return "custom";
  default:
    return "deadlock";
  }
}

bool runs_on_fingerprint_store(const Property& property) {
  return property.kind == PropertyKind::invariant || property.kind == PropertyKind::deadlock ||
         (property.kind == PropertyKind::custom && property.fingerprint_store);
}

namespace {

// For a trace of a property with a legal set (L; L2 of a transitivity check), whether each of
// its states is in it: what a reader of a stabilisation witness looks for first.
void mark_legal_set(PropertyResult& result, const Property& property) {
  const bool has_legal_set = property.kind == PropertyKind::stabilisation ||
                             property.kind == PropertyKind::transitivity ||
                             property.kind == PropertyKind::legal_set;
  if (!has_legal_set || !result.trace || !property.predicate)
    return;
  result.legal_set_name = property.predicate_name.empty() ? "L" : property.predicate_name;
  result.trace_in_legal_set.clear();
  for (const TraceStep& step : result.trace->steps)
    result.trace_in_legal_set.push_back(property.predicate(tioa::State(step.state.data(), 0)));
}

PropertyResult run_check(const Automaton& system, const Property& property,
                         const StatePredicate& predicate, const ExploreOptions& named) {
  switch (property.kind) {
  case PropertyKind::invariant:
    return check_invariant(system, predicate, named);
  case PropertyKind::legal_set:
    return check_legal_set(system, predicate, named);
  case PropertyKind::stabilisation:
    return check_stabilisation(system, predicate, named);
  case PropertyKind::transitivity:
    return check_transitivity(system, property.first, property.first_name, predicate,
                              property.predicate_name, named);
  case PropertyKind::deadlock:
    return check_no_deadlock(system, named, predicate, property.predicate_name);
  case PropertyKind::custom:
    break;
  }
  return property.run(named);
}

bool ends_beyond(const PropertyResult& r, const StatePredicate& beyond) {
  return r.trace && !r.trace->steps.empty() &&
         beyond(tioa::State(r.trace->steps.back().state.data(), 0));
}

// A state past the bound has no step. The first run counts it as a violation (outside the
// invariant or L, or a deadlock), so that a run that finds nothing has reached none; the
// second counts it as fine (in the invariant or L, a proper end), so that what it finds
// is a violation within the bound.
PropertyResult run_within_bound(const Automaton& system, const Property& property,
                                const ExploreOptions& named) {
  const StatePredicate& beyond = property.beyond_bound;
  const StatePredicate& given = property.predicate;
  const StatePredicate strict =
      property.kind == PropertyKind::deadlock && !given
          ? StatePredicate{}
          : StatePredicate([&](const tioa::State& s) { return !beyond(s) && given(s); });
  PropertyResult first = run_check(system, property, strict, named);
  if (first.verdict != Verdict::violated || !ends_beyond(first, beyond))
    return first;
  const StatePredicate lenient = [&](const tioa::State& s) {
    return beyond(s) || (given && given(s));
  };
  PropertyResult second = run_check(system, property, lenient, named);
  const std::string exceeded = property.bound_name + " is exceeded after " +
                               std::to_string(first.trace->length()) + " steps";
  second.seconds += first.seconds;
  if (second.verdict == Verdict::violated) {
    second.notes.push_back(exceeded + " on another path; this counterexample stays within it");
    return second;
  }
  second.notes.push_back("the first run (" + std::to_string(first.states) + " states) found that " +
                         exceeded + " (the trace)");
  if (second.verdict == Verdict::holds)
    second.message = "holds on every state reached within the bound, but " + exceeded +
                     ": raise it to check beyond";
  second.verdict = Verdict::incomplete;
  // A worst time that counts the states past the bound as in L claims too little.
  second.worst_time.reset();
  second.last_time_outside.reset();
  second.trace = first.trace;
  second.trace_role = "witness";
  second.trace_kind = "bound";
  return second;
}

} // namespace

PropertyResult run_property(const Automaton& system, const Property& property,
                            const ExploreOptions& options) {
  // The other checks read the stored states after the run (a set of them, edges, a
  // relation), which the fingerprint store does not keep.
  if (options.store == StoreKind::fingerprint && !runs_on_fingerprint_store(property))
    throw std::invalid_argument("property '" + property.name + "' (" + to_string(property.kind) +
                                ") cannot run on the " + to_string(options.store) +
                                " store: use the exact store");
  ExploreOptions named = options;
  named.task = property.name;
  // --max-seconds is a budget for the whole property, however many explorations it runs;
  // a deadline set by the caller (a suite's) stays.
  if (named.limits.max_seconds > 0 && !named.limits.deadline)
    named.limits.deadline = std::chrono::steady_clock::now() +
                            std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(named.limits.max_seconds));
  // --max-states likewise (options.hpp, StatesBudget); a budget set by the caller stays.
  if (named.limits.max_states > 0 && !named.limits.states_budget) {
    named.limits.states_budget = std::make_shared<StatesBudget>();
    named.limits.states_budget->max = named.limits.max_states;
  }
  if (named.limits.max_memory_bytes > 0 && named.limits.resident_base == 0)
    named.limits.resident_base = resident_bytes();
  const bool bounded = property.beyond_bound && (property.kind == PropertyKind::invariant ||
                                                 property.kind == PropertyKind::stabilisation ||
                                                 property.kind == PropertyKind::deadlock);
  PropertyResult result = bounded ? run_within_bound(system, property, named)
                                  : run_check(system, property, property.predicate, named);
  result.name = property.name;
  result.description = property.description;
  mark_legal_set(result, property);
  claim_only_covered(result);
  return result;
}

} // namespace checker
