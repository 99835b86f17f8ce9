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

} // namespace

PropertyResult run_property(const Automaton& system, const Property& property,
                            const ExploreOptions& options) {
  if (options.store == StoreKind::fingerprint && !runs_on_fingerprint_store(property))
    throw std::invalid_argument("property '" + property.name + "' (" + to_string(property.kind) +
                                ") cannot run on the fingerprint store: use the exact store");
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
  PropertyResult result;
  switch (property.kind) {
  case PropertyKind::invariant:
    result = check_invariant(system, property.predicate, named);
    break;
  case PropertyKind::legal_set:
    result = check_legal_set(system, property.predicate, named);
    break;
  case PropertyKind::stabilisation:
    result = check_stabilisation(system, property.predicate, named);
    break;
  case PropertyKind::transitivity:
    result = check_transitivity(system, property.first, property.first_name, property.predicate,
                                property.predicate_name, named);
    break;
  case PropertyKind::deadlock:
    result = check_no_deadlock(system, named, property.predicate, property.predicate_name);
    break;
  case PropertyKind::custom:
    result = property.run(named);
    break;
  }
  result.name = property.name;
  result.description = property.description;
  mark_legal_set(result, property);
  claim_only_covered(result);
  return result;
}

} // namespace checker
