#pragma once
// What check, explore and walk run on: the instance's system, or U of it (--from
// arbitrary), with its start states narrowed to those that satisfy --start; and the
// invariant given with --invariant.

#include <string>

#include "checker/property.hpp"
#include "cli/model_run.hpp"

namespace cli {

// `from` is "start" or "arbitrary" (U of the system); `start`, when not empty, an
// expression over the variables (checker/state_expression.hpp) whose states are the start
// states instead: every valuation where it holds, the variables it does not name arbitrary.
// Throws UsageError for a bad expression, or one that no state satisfies.
tioa::Automaton run_system(const BuiltModel& built, const std::string& from,
                           const std::string& start);

// The predicate of `--start EXPR`. Throws UsageError for a bad expression.
tioa::StatePredicate start_predicate(const tioa::StateLayout& layout, const std::string& text);

// The property `--invariant EXPR` checks, named "invariant". Throws UsageError for a bad
// expression.
checker::Property given_invariant(const tioa::StateLayout& layout, const std::string& text);
// The same, with the bound of the model's states (ModelInstance::beyond_bound).
checker::Property given_invariant(const tioa::StateLayout& layout, const std::string& text,
                                  const catalogue::ModelInstance& instance);

// The name of the property given_invariant makes.
inline constexpr const char* given_invariant_name = "invariant";

} // namespace cli
