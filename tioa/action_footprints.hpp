#pragma once
// The footprint of each action of an automaton over its whole parameter box: what any of
// its steps may read and write (tioa/footprint.hpp).

#include <vector>

#include "tioa/automaton.hpp"

namespace tioa {

// Boxes with more points than this are not enumerated: such an action may read and write
// everything.
inline constexpr double max_footprint_box = 65536;

std::vector<ActionFootprint> action_footprints(const Automaton& automaton);

} // namespace tioa
