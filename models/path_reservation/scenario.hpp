#pragma once
// The built-in scenarios of the path-reservation model: a plane, the communication range
// C, and one path per robot (its waypoints; chunk k runs from waypoint k to k+1).

#include <optional>
#include <string>
#include <vector>

#include "models/path_reservation/geometry.hpp"
#include "models/path_reservation/precedence.hpp"

namespace path_reservation {

inline constexpr int max_chunks = 7;

struct Scenario {
  std::string name;
  std::string description;
  int width = 1, height = 1;
  int range = 4; // C, in cells: robots closer than C hear each other (§2)
  std::vector<std::vector<Cell>> paths;

  int robots() const { return static_cast<int>(paths.size()); }
  int chunks(int robot) const { return static_cast<int>(paths[robot].size()) - 1; }
};

const std::vector<Scenario>& scenarios();
std::vector<std::string> scenario_names();
const Scenario& find_scenario(const std::string& name); // throws std::invalid_argument

// Why the scenario cannot be modelled, or nullopt: the plane, the number of robots and
// chunks, straight chunks, distinct start cells, and Definition 4 (every zone lies in
// Cir(start of its chunk, C/2), a closed or an open disk).
std::optional<std::string> check_scenario(const Scenario& scenario,
                                          DiskEdge edge = DiskEdge::closed);

} // namespace path_reservation
