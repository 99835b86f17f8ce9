#pragma once
// The model `mc-round`: the motion-coordination algorithm at round level (seed 002 §VI,
// seed 000 §6) on an m×m grid, for the command line and the suite.

#include "catalogue/registry.hpp"

namespace catalogue {

ModelDefinition mc_round_definition();

} // namespace catalogue
