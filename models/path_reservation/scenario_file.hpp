#pragma once
// A scenario of the path-reservation model read from a text file, one statement a line
// ('#' starts a comment; blank lines are ignored):
//
//   name my-crossing                  (default: the file's stem)
//   description two robots crossing   (default: "scenario file <path>")
//   plane 4 4                         width and height in cells, at most 64 cells
//   range 6                           the communication range C, in cells
//   robot (0,2) (3,2)                 one line a robot: its waypoints
//
// plane, range and at least one robot are required. The result passes check_scenario.

#include <iosfwd>
#include <string>

#include "models/path_reservation/scenario.hpp"

namespace path_reservation {

// Every error throws std::invalid_argument with one line "<path>:<line>: <what is wrong>",
// or "<path>: <what is wrong>" when no line is to blame (cannot open, check_scenario).
Scenario read_scenario_file(const std::string& path);
Scenario parse_scenario(std::istream& in, const std::string& source_name);

// The scenario as a file that parse_scenario reads back to it (a description with '#' in it
// loses what follows; none of ours has one).
std::string scenario_file_text(const Scenario& scenario);

} // namespace path_reservation
