#pragma once
// The model `vlayer-mc`: VLayer[MC] (seed 000 Def 4.1, §5.5) over discretised time, for the
// command line and the suite (issue 4 parameter names).

#include "catalogue/registry.hpp"
#include "models/vlayer_mc/config.hpp"

namespace catalogue {

// The configuration the parameters name.
vlayer_mc::VlConfig vlayer_config(const ParamValues& params);
ModelDefinition vlayer_mc_definition();

} // namespace catalogue
