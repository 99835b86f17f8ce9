#pragma once
// Composition A1 || ... || An (seed 000 §3.1, "Composition") and hiding.
//
// Each component keeps its own variables (placed one after the other in the composite
// state, named "component.variable"); an output or internal action of one component
// runs together with the matching input of every other component whose parameter box
// contains the occurrence. Compatibility (§3.1): no shared variables (a component may
// appear once), no output shared by two components, no internal action of one that is
// an action of another; a violation is a ModelError naming both components.
//
// Decisions: an input of a component stays an input of the composite for the parameter
// values that no component outputs; same-named inputs of several components become one
// input of the composite (over the smallest box holding theirs, accepting exactly the
// values of the union of their boxes), and every component whose box holds a value
// receives it.

#include <string>
#include <vector>

#include "tioa/automaton.hpp"

namespace tioa {

inline constexpr std::size_t max_components = 64;

Automaton compose(const std::string& name, const std::vector<Automaton>& components);
Automaton operator||(const Automaton& a, const Automaton& b);

// The same automaton with the named outputs turned into internal actions.
Automaton hide(const Automaton& automaton, const std::vector<std::string>& outputs);

} // namespace tioa
