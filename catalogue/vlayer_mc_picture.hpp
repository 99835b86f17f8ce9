#pragma once
// The picture of a vlayer-mc state (models/vlayer_mc/README.md): the grid of regions with
// their lattice points, the curve Γ, each VSA live or failed with its clock, each robot at
// RW.loc with a dashed line to its target x*_p, and the messages in flight (VBDelay and
// VBcast) as arrows, listed underneath in words. Read from the state's named variables: a
// variable the model does not have is left out of the picture.

#include <ostream>
#include <string>

#include "catalogue/registry.hpp"

namespace catalogue {

// `params` is the report's "params" object (rows, cols, nbh, b, robots); `state` a trace
// step's "state" object; `id` makes the picture's element ids unique on the page.
void write_vlayer_mc_picture(std::ostream& out, const Json& params, const Json& state,
                             const std::string& id);

} // namespace catalogue
