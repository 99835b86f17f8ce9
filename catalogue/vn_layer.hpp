#pragma once
// The model `vn-layer`: the conference virtual-node layer (seed 001 Figs. 2–3, seed 002
// Figs. 5–6) over discretised time, for the command line and the suite.

#include "catalogue/registry.hpp"
#include "models/vn_layer/config.hpp"

namespace catalogue {

// The configuration the parameters name.
vn_layer::VnConfig vn_layer_config(const ParamValues& params);
ModelDefinition vn_layer_definition();

} // namespace catalogue
