#include "models/path_reservation/geometry.hpp"

#include <climits>
#include <cstdlib>
#include <stdexcept>

namespace path_reservation {

Plane::Plane(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width * height > 64)
    throw std::invalid_argument("a plane of " + std::to_string(width) + "x" +
                                std::to_string(height) + " cells (at most 64 cells)");
}

std::vector<Cell> Plane::chunk_cells(Cell from, Cell to) const {
  if (!contains(from) || !contains(to))
    throw std::invalid_argument("chunk " + to_string(from) + "-" + to_string(to) +
                                " leaves the plane");
  const int dx = to.x - from.x, dy = to.y - from.y;
  if (dx == 0 && dy == 0)
    throw std::invalid_argument("chunk " + to_string(from) + "-" + to_string(to) + " is empty");
  if (dx != 0 && dy != 0 && std::abs(dx) != std::abs(dy))
    throw std::invalid_argument("chunk " + to_string(from) + "-" + to_string(to) +
                                " is not horizontal, vertical or diagonal");
  const int steps = std::max(std::abs(dx), std::abs(dy));
  const int sx = dx == 0 ? 0 : dx / std::abs(dx), sy = dy == 0 ? 0 : dy / std::abs(dy);
  std::vector<Cell> out;
  for (int k = 0; k <= steps; ++k)
    out.push_back({from.x + k * sx, from.y + k * sy});
  return out;
}

Zone Plane::zone(Cell from, Cell to) const {
  Zone z;
  z.pre = bit(from);
  z.post = bit(to);
  for (Cell c : chunk_cells(from, to))
    z.motion |= bit(c);
  return z;
}

CellSet Plane::disk(Cell centre, int squared_radius_times_4, DiskEdge edge) const {
  CellSet out = 0;
  for (int i = 0; i < cells(); ++i) {
    const int d4 = 4 * path_reservation::squared_distance(centre, cell(i));
    if (d4 < squared_radius_times_4 || (d4 == squared_radius_times_4 && edge == DiskEdge::closed))
      out |= CellSet{1} << i;
  }
  return out;
}

int Plane::squared_distance(Cell from, CellSet area) const {
  int best = INT_MAX;
  for (int i = 0; i < cells(); ++i)
    if (area >> i & 1)
      best = std::min(best, path_reservation::squared_distance(from, cell(i)));
  return best;
}

std::string to_string(Cell c) {
  return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")";
}

} // namespace path_reservation
