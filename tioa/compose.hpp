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
// Decisions: an input is removed from the composite's signature when some component
// has an output of the same name, and same-named unmatched inputs merge into one input
// whose box is the smallest box holding all of them.

#include <string>
#include <vector>

#include "tioa/automaton.hpp"

namespace tioa {

Automaton compose(const std::string& name, const std::vector<Automaton>& components);
Automaton operator||(const Automaton& a, const Automaton& b);

// The same automaton with the named outputs turned into internal actions.
Automaton hide(const Automaton& automaton, const std::vector<std::string>& outputs);

} // namespace tioa
