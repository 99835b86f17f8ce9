#pragma once
// The model `path-reservation`: the collision-avoidance protocol of seed 004 on the
// built-in scenarios or one read from a file, with the properties of its §6 (issue 5
// names).

#include "catalogue/registry.hpp"
#include "models/path_reservation/protocol.hpp"

namespace catalogue {

// The scenario the parameters name: `scenario_file` when given, else `scenario`. A file
// that cannot be read or checked throws tioa::ModelError with one line.
path_reservation::Scenario chosen_scenario(const ParamValues& params);
// The protocol the parameters name (the scenario and the readings).
path_reservation::Protocol path_reservation_protocol(const ParamValues& params);
ModelDefinition path_reservation_definition();

} // namespace catalogue
