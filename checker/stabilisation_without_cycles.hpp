#pragma once
// The stabilisation check (stabilisation.cpp) on a graph with no cycle, with the
// partial-order reduction: for an untimed automaton that declares a progress measure
// (Automaton::set_progress_measure), every execution is finite and ends in a state with
// no step, so "every execution is in L from some point on" says exactly that every
// reachable state with no step is in L. The stubborn sets keep every such state
// (zero_time_reduction.hpp), so the reduced graph decides the verdict; it does not keep
// the longest execution, so no worst time is measured.

#include <optional>

#include "checker/checks.hpp"

namespace checker {

// The verdict by this route; nullopt when it does not apply: no options.por, a timed
// automaton, no progress measure, or no footprint that lets a set be smaller than every
// enabled step (then the full check, which also measures the worst time, costs little
// more).
std::optional<PropertyResult> check_stabilisation_without_cycles(const Automaton& system,
                                                                 const StatePredicate& legal,
                                                                 const ExploreOptions& options);

} // namespace checker
