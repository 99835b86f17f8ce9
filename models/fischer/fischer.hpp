#pragma once
// Fischer's mutual exclusion protocol in discrete time, exactly as
// ../shared/peer-models.md (b).

#include "models/registry.hpp"

namespace models {

ModelInstance build_fischer(int n, int a, int b);
ModelDefinition fischer_definition();

} // namespace models
