#pragma once
// The model `fischer` (models/fischer): its properties and suite entries.

#include "catalogue/registry.hpp"

namespace catalogue {

ModelInstance build_fischer(int n, int a, int b);
ModelDefinition fischer_definition();

} // namespace catalogue
