#include "checker/property.hpp"

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

PropertyResult run_property(const Automaton& system, const Property& property,
                            const ExploreOptions& options) {
  ExploreOptions named = options;
  named.task = property.name;
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
    result = check_no_deadlock(system, named);
    break;
  case PropertyKind::custom:
    result = property.run(named);
    break;
  }
  result.name = property.name;
  result.description = property.description;
  return result;
}

} // namespace checker
