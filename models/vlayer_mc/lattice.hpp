#pragma once
// The deployment space of the timed model on a lattice (models/vlayer_mc/README.md,
// "Discretisation"): a rows×cols grid tiling (seed 000 §4.1) of b×b regions, positions at
// the integer points of [0, cols·b] × [0, rows·b], y downward, region u = row·cols + col.
// b is even, so that every region centre o_u is a lattice point.

#include <cstdint>
#include <vector>

#include "models/mc/grid.hpp"

namespace vlayer_mc {

using Point = int; // index y·width + x of a lattice point
using RegionId = int;

class Lattice {
public:
  // Throws std::invalid_argument unless rows, cols >= 1 and b >= 2 is even.
  Lattice(int rows, int cols, int b, mc::Neighbourhood neighbourhood);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  int b() const { return b_; }
  mc::Neighbourhood neighbourhood() const { return neighbourhood_; }
  int width() const { return cols_ * b_ + 1; }
  int height() const { return rows_ * b_ + 1; }
  int points() const { return width() * height(); }
  int regions() const { return rows_ * cols_; }

  Point point(int x, int y) const { return y * width() + x; }
  int x_of(Point p) const { return p % width(); }
  int y_of(Point p) const { return p / width(); }

  // The region that owns p (D14: half-open squares; the last row and column own their far
  // sides), as mc::CurveOnGrid.
  RegionId region_of(Point p) const;
  Point centre(RegionId u) const; // o_u
  // nbrs(u) in increasing id order (4: shared side; 8: shared side or corner).
  const std::vector<RegionId>& nbrs(RegionId u) const {
    return neighbours_[static_cast<std::size_t>(u)];
  }
  bool in_nbrs_plus(RegionId u, RegionId v) const; // v ∈ nbrs+(u)

  int distance(Point a, Point b) const; // L∞
  // One quantum of motion at speed vmax towards `to` (D8): each coordinate moves by up to
  // vmax, stopping on the target.
  Point step_toward(Point from, Point to, int vmax) const;
  // r: the largest L∞ distance between points of neighbouring regions (seed 000 §4.1);
  // b on a grid without neighbours (1×1).
  int r() const;

private:
  int rows_, cols_, b_;
  mc::Neighbourhood neighbourhood_;
  std::vector<std::vector<RegionId>> neighbours_;
};

} // namespace vlayer_mc
