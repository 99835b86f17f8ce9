#include "models/vlayer_mc/config.hpp"

namespace vlayer_mc {

int round_length_bound(const VlConfig& c) {
  const int r = c.lattice().r();
  return 2 * c.e + 3 * c.d + 2 * c.eps + (r + c.vmax - 1) / c.vmax + c.d_r;
}

bool round_length_ok(const VlConfig& c) {
  return c.delta > round_length_bound(c);
}

std::optional<std::string> invalid(const VlConfig& c) {
  if (c.rows < 1 || c.cols < 1 || c.rows * c.cols > 9)
    return "the grid must have 1 to 9 regions";
  if (c.b < 2 || c.b % 2 != 0 || c.b > 8)
    return "b must be even, 2..8";
  if (c.robots < 1 || c.robots > 6)
    return "robots must be 1..6";
  if (c.d < 1 || c.e < 0 || c.eps < 0 || c.eps_sample < 1 || c.d_r < 0 || c.vmax < 1)
    return "need d >= 1, e >= 0, eps >= 0, eps_sample >= 1, d_r >= 0, vmax >= 1";
  if (c.delta < 2 || c.delta > 64)
    return "delta must be 2..64";
  if (c.target_phase() >= c.delta)
    return "the target phase e + 2d + 2eps must fall inside the round (< delta)";
  if (c.eps_sample >= c.delta)
    return "eps_sample must be < delta";
  if (c.junk < 0 || c.junk > 3)
    return "junk must be 0..3";
  if (c.k < 1)
    return "k must be >= 1";
  if (c.rho1 <= 0 || c.rho1 >= 1 || c.rho2 <= 0 || c.rho2 >= 1)
    return "rho1 and rho2 must lie in (0, 1)";
  // Last: the lattice needs the values above.
  if (c.place == Placement::row && c.robots > c.lattice().width())
    return "place=row puts robot p at x = p: " + std::to_string(c.robots) +
           " robots need a lattice " + std::to_string(c.robots) + " points wide, this one has " +
           std::to_string(c.lattice().width()) + " (place=corner, or a larger cols or b)";
  return std::nullopt;
}

} // namespace vlayer_mc
