#pragma once
// The model `path-reservation`: the collision-avoidance protocol of seed 004 on the
// built-in scenarios, with the properties of its §6 (issue 5 names).

#include "models/path_reservation/protocol.hpp"
#include "models/registry.hpp"

namespace models {

// The protocol the parameters name (scenario, sort, variant).
path_reservation::Protocol path_reservation_protocol(const ParamValues& params);
ModelDefinition path_reservation_definition();

} // namespace models
