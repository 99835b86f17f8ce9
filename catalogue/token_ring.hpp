#pragma once
// The model `token-ring` (models/token_ring): its properties and suite entries.

#include "catalogue/registry.hpp"

namespace catalogue {

ModelInstance build_token_ring(int n, int k);
ModelDefinition token_ring_definition();

} // namespace catalogue
