#pragma once
// The picture of a path-reservation state (models/path_reservation/README.md): the plane's
// cells, each robot's path and waypoints in its own colour, the area each robot owns
// (shaded) and the zone it requests (dashed, with its Pre and Post cells marked), each
// robot at its cell (a halted one ringed in red with its exception), and the messages in
// flight as arrows, listed underneath in words with a table of each robot's phase, chunk,
// G_i and WLAfter lists. Read from the state's named variables: a variable the model does
// not have is left out of the picture.

#include <ostream>
#include <string>

#include "catalogue/registry.hpp"

namespace catalogue {

// `params` is the report's "params" object (its "scenario" names the plane and the paths);
// `state` a trace step's "state" object; `id` makes the picture's element ids unique on
// the page.
void write_path_reservation_picture(std::ostream& out, const Json& params, const Json& state,
                                    const std::string& id);

} // namespace catalogue
