#pragma once
// A scenario's paths cut into chunks, computed once: each chunk's cells (in the order the
// robot covers them) and its zone. Robots are 1-based here, as in the paper's R_i.

#include "models/path_reservation/scenario.hpp"

namespace path_reservation {

struct PathGeometry {
  Plane plane;
  Scenario scenario;
  std::vector<std::vector<std::vector<Cell>>> cells; // [robot - 1][chunk]
  std::vector<std::vector<Zone>> zones;              // [robot - 1][chunk]
  std::vector<CellSet> reservation_disk;             // [cell]: Cir(cell, C/2), Definition 4

  explicit PathGeometry(const Scenario& s, DiskEdge edge = DiskEdge::closed)
      : plane(s.width, s.height), scenario(s) {
    for (int r = 0; r < s.robots(); ++r) {
      cells.emplace_back();
      zones.emplace_back();
      for (int k = 0; k < s.chunks(r); ++k) {
        cells[r].push_back(plane.chunk_cells(s.paths[r][k], s.paths[r][k + 1]));
        zones[r].push_back(plane.zone(s.paths[r][k], s.paths[r][k + 1]));
      }
    }
    for (int c = 0; c < plane.cells(); ++c)
      reservation_disk.push_back(plane.disk(plane.cell(c), s.range * s.range, edge));
  }
  const Zone& zone(int robot, int chunk) const { return zones[robot - 1][chunk]; }
  int last_chunk(int robot) const { return scenario.chunks(robot - 1) - 1; }
  Cell start(int robot, int chunk) const { return scenario.paths[robot - 1][chunk]; }
  Cell end(int robot) const { return scenario.paths[robot - 1].back(); }
  int range_squared() const { return scenario.range * scenario.range; }
};

} // namespace path_reservation
