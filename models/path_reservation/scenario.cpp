#include "models/path_reservation/scenario.hpp"

#include <stdexcept>

namespace path_reservation {

namespace {

std::string robot_name(int r) {
  return "R" + std::to_string(r + 1);
}

} // namespace

// Each scenario is small enough to explore exhaustively; the verdicts are pinned in
// tests/models/path_reservation/ and discussed in models/path_reservation/README.md.
const std::vector<Scenario>& scenarios() {
  static const std::vector<Scenario> all{
      {"crossing",
       "two robots whose chunks cross in their motion zones (a Conflict, Definition 7)",
       4,
       4,
       6,
       {{{0, 2}, {3, 2}}, {{2, 0}, {2, 3}}}},
      {"head-on",
       "two robots meet head-on in a one-cell corridor: both zones end on the same cell",
       5,
       1,
       5,
       {{{0, 0}, {2, 0}, {4, 0}}, {{4, 0}, {2, 0}, {0, 0}}}},
      {"convoy",
       "three robots in a corridor, each following the one ahead into the cell it leaves",
       7,
       1,
       5,
       {{{4, 0}, {6, 0}}, {{2, 0}, {4, 0}}, {{0, 0}, {2, 0}}}},
      {"cycle",
       "three robots on a cycle of three cells, each moving into the cell of the next",
       2,
       2,
       3,
       {{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 0}}}},
      {"late-joiner",
       "two robots cross while a third, whose path crosses the first's later, may join at "
       "any moment of their negotiation",
       5,
       4,
       6,
       {{{0, 2}, {2, 2}, {4, 2}}, {{2, 0}, {2, 3}}, {{4, 0}, {4, 3}}}},
      {"range-edge",
       "two robots exactly C apart whose zones meet on the middle cell: Definition 4's closed "
       "disk allows both zones, and the robots cannot hear each other (finding P3)",
       5,
       1,
       4,
       {{{0, 0}, {2, 0}}, {{4, 0}, {2, 0}}}},
      {"pinwheel",
       "four robots on four lines around a square: each path crosses two others in motion",
       4,
       4,
       7,
       {{{0, 1}, {3, 1}}, {{2, 0}, {2, 3}}, {{3, 2}, {0, 2}}, {{1, 3}, {1, 0}}}},
      // Convoys with two chunks each (issue 16). Each robot hears the robots 2 and 4 cells
      // ahead and behind (C = 5) until they pull apart. convoy-3x2 shows findings P6 and P7
      // (README, "Findings"); convoy-5x2 (3.5·10^7 states) is explored completely in 3 to
      // 6 minutes a property on two cores.
      {"convoy-3x2",
       "three robots in a corridor with two chunks each, each following the one ahead into "
       "the cell it leaves",
       9,
       1,
       5,
       {{{4, 0}, {6, 0}, {8, 0}}, {{2, 0}, {4, 0}, {6, 0}}, {{0, 0}, {2, 0}, {4, 0}}}},
      {"convoy-5x2",
       "five robots in a corridor with two chunks each, each following the one ahead into "
       "the cell it leaves",
       13,
       1,
       5,
       {{{8, 0}, {10, 0}, {12, 0}},
        {{6, 0}, {8, 0}, {10, 0}},
        {{4, 0}, {6, 0}, {8, 0}},
        {{2, 0}, {4, 0}, {6, 0}},
        {{0, 0}, {2, 0}, {4, 0}}}},
  };
  return all;
}

std::vector<std::string> scenario_names() {
  std::vector<std::string> names;
  for (const auto& s : scenarios())
    names.push_back(s.name);
  return names;
}

const Scenario& find_scenario(const std::string& name) {
  for (const auto& s : scenarios())
    if (s.name == name)
      return s;
  throw std::invalid_argument("unknown scenario '" + name + "'");
}

std::optional<std::string> check_scenario(const Scenario& s, DiskEdge edge) {
  if (s.robots() < 1 || s.robots() > max_robots)
    return "a scenario has 1.." + std::to_string(max_robots) + " robots";
  if (s.range < 1)
    return "the communication range C must be at least 1";
  try {
    const Plane plane(s.width, s.height);
    CellSet starts = 0;
    for (int r = 0; r < s.robots(); ++r) {
      if (s.chunks(r) < 1 || s.chunks(r) > max_chunks)
        return robot_name(r) + " needs 1.." + std::to_string(max_chunks) + " chunks";
      if (!plane.contains(s.paths[r][0]))
        return robot_name(r) + " starts outside the plane";
      if (starts & plane.bit(s.paths[r][0]))
        return robot_name(r) + " starts on the cell of another robot";
      starts |= plane.bit(s.paths[r][0]);
      for (int k = 0; k < s.chunks(r); ++k) {
        const Cell from = s.paths[r][k], to = s.paths[r][k + 1];
        // Before any bit of it is taken: a cell off the plane has no bit (issue 17, UBSan).
        if (!plane.contains(to))
          return robot_name(r) + "'s waypoint " + to_string(to) + " is outside the plane";
        const Zone zone = plane.zone(from, to); // throws when the chunk is not straight
        if ((zone.all() & ~plane.disk(from, s.range * s.range, edge)) != 0)
          return robot_name(r) + "'s chunk " + to_string(from) + "-" + to_string(to) +
                 " leaves the " + (edge == DiskEdge::closed ? "closed" : "open") + " disk Cir(" +
                 to_string(from) + ", C/2) (Definition 4)";
      }
    }
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return std::nullopt;
}

} // namespace path_reservation
