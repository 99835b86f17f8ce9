#pragma once
// A named property of a model, as the command line and the suite see it, and the one
// function that runs it with the right check.

#include <functional>
#include <string>

#include "checker/checks.hpp"

namespace checker {

enum class PropertyKind { invariant, legal_set, stabilisation, transitivity, deadlock, custom };

const char* to_string(PropertyKind kind);

struct Property {
  std::string name;
  std::string description;
  PropertyKind kind = PropertyKind::invariant;
  // The invariant, the legal set L (L2 for transitivity), or for a deadlock check the states
  // that are proper ends (check_no_deadlock's `ended`; empty: none). A custom check may
  // name the set its traces are about (`replay` evaluates them on it).
  StatePredicate predicate;
  std::string predicate_name;
  StatePredicate first; // transitivity: the intermediate legal set L1
  std::string first_name;
  // custom: a check of its own (e.g. a lemma over a family of instances, proofs/).
  std::function<PropertyResult(const ExploreOptions&)> run = {};
  // custom: whether `run` accepts the fingerprint store (it runs check_invariant or
  // check_no_deadlock and reads nothing else of a search, or reads the stored states only
  // where the store keeps them). Every check runs on the compressed store: they read the
  // stored states through StateReader (exploration.hpp).
  bool fingerprint_store = false;
  // The states past a bound of the model (a channel that a send found full): the model
  // stops there, and such a state stands for continuations it cannot hold. Empty: none.
  // An invariant, stabilisation or deadlock check that reaches one is incomplete, unless
  // it finds a violation on a path that stays within the bound (run_property).
  StatePredicate beyond_bound = {};
  std::string bound_name = ""; // what was exceeded, in words: "a channel of capacity 4"
};

// Whether the property may run on the fingerprint store (ExploreOptions::store):
// invariants and deadlocks, whose checks read nothing of the search but its counts, its
// parents and the states they keep (checks.hpp), and the custom checks that say so.
bool runs_on_fingerprint_store(const Property& property);

// Throws std::invalid_argument for a property that cannot run on the store `options` ask
// for (runs_on_fingerprint_store()). With a `beyond_bound`, a first run takes the states
// past the bound as violations; only when its counterexample ends in one, a second run
// takes them as fine, to look for a violation within the bound (else: incomplete, with the
// path that leaves the bound as a trace of kind "bound").
PropertyResult run_property(const Automaton& system, const Property& property,
                            const ExploreOptions& options);

} // namespace checker
