#include "models/vlayer_mc/lattice.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace vlayer_mc {

Lattice::Lattice(int rows, int cols, int b, mc::Neighbourhood neighbourhood)
    : rows_(rows), cols_(cols), b_(b), neighbourhood_(neighbourhood) {
  if (rows < 1 || cols < 1)
    throw std::invalid_argument("the grid needs at least one row and one column");
  if (b < 2 || b % 2 != 0)
    throw std::invalid_argument(
        "the region side b must be even and at least 2 (centres on the lattice)");
  neighbours_.resize(static_cast<std::size_t>(regions()));
  for (int u = 0; u < regions(); ++u)
    for (int v = 0; v < regions(); ++v) {
      const int dr = std::abs(u / cols - v / cols), dc = std::abs(u % cols - v % cols);
      const bool side = dr + dc == 1;
      const bool corner = dr == 1 && dc == 1;
      if (side || (corner && neighbourhood == mc::Neighbourhood::eight))
        neighbours_[static_cast<std::size_t>(u)].push_back(v);
    }
}

RegionId Lattice::region_of(Point p) const {
  const int col = std::min(x_of(p) / b_, cols_ - 1);
  const int row = std::min(y_of(p) / b_, rows_ - 1);
  return row * cols_ + col;
}

Point Lattice::centre(RegionId u) const {
  return point((u % cols_) * b_ + b_ / 2, (u / cols_) * b_ + b_ / 2);
}

bool Lattice::in_nbrs_plus(RegionId u, RegionId v) const {
  const auto& n = nbrs(u);
  return u == v || std::find(n.begin(), n.end(), v) != n.end();
}

int Lattice::distance(Point a, Point b) const {
  return std::max(std::abs(x_of(a) - x_of(b)), std::abs(y_of(a) - y_of(b)));
}

Point Lattice::step_toward(Point from, Point to, int vmax) const {
  const auto move = [vmax](int a, int b) { return a + std::clamp(b - a, -vmax, vmax); };
  return point(move(x_of(from), x_of(to)), move(y_of(from), y_of(to)));
}

int Lattice::r() const {
  int r = 0;
  for (Point a = 0; a < points(); ++a)
    for (Point c = 0; c < points(); ++c)
      if (region_of(a) != region_of(c) && in_nbrs_plus(region_of(a), region_of(c)))
        r = std::max(r, distance(a, c));
  return r == 0 ? b_ : r;
}

} // namespace vlayer_mc
