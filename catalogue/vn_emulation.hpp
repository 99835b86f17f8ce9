#pragma once
// The model `vn-emulation`: the VN emulation of seed 002 §VIII (TOBcast, VNE, join/reset)
// on one zone, over discretised time, for the command line and the suite.

#include "catalogue/registry.hpp"
#include "models/vn_emulation/config.hpp"

namespace catalogue {

// The configuration the parameters name.
vn_emulation::EmuConfig vn_emulation_config(const ParamValues& params);
ModelDefinition vn_emulation_definition();

} // namespace catalogue
