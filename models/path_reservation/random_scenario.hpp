#pragma once
// Scenarios drawn at random (issue 16, `scenario=random`): a square plane, robots with
// straight chunks, drawn from a seed so that one seed is one scenario on every machine.
//
// A drawn scenario is valid as a built-in one is (check_scenario, Definition 4 with the
// closed disk), and more (README, "Random scenarios"):
//  - the communication range C is the plane's side, so a chunk runs at most C/2 cells
//    (Definition 4) and robots on one plane can hear each other across half of it;
//  - every chunk moves (it ends on another cell than it starts), start cells are distinct
//    and so are end cells (two robots that end on one cell cannot both finish);
//  - the robots are near enough to meet: the graph whose edges join two robots whose paths
//    share a cell is connected, so no robot runs alone.
// Draws that break a rule are dropped and drawn again from the same generator.

#include <cstdint>
#include <string>

#include "models/path_reservation/scenario.hpp"

namespace path_reservation {

struct RandomScenarioSpec {
  std::uint64_t seed = 1;
  int robots = 3;
  int chunks = 2; // per robot
  int plane = 4;  // side, in cells (2..8)
};

// Throws std::invalid_argument with one line when the sizes are out of range or no valid
// scenario is found within a fixed number of draws.
Scenario random_scenario(const RandomScenarioSpec& spec);

} // namespace path_reservation
