#pragma once
// Dijkstra's K-state self-stabilising token ring, exactly as ../shared/peer-models.md (a).

#include "models/registry.hpp"

namespace models {

ModelInstance build_token_ring(int n, int k);
ModelDefinition token_ring_definition();

} // namespace models
