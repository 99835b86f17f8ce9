#include "models/vn_layer/config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vn_layer {

vlayer_mc::VlConfig VnConfig::targets_config() const {
  vlayer_mc::VlConfig c;
  c.rows = rows;
  c.cols = cols;
  c.nbh = nbh;
  c.robots = cns;
  c.b = b;
  c.k = k;
  c.rho1 = rho1;
  c.rho2 = rho2;
  c.owned_ends = owned_ends;
  c.branch_tally = branch_tally;
  return c;
}

namespace {

int messaging(const VnConfig& c) {
  return 2 * c.d_mmt + 5 * c.d_v + 2 * c.eps;
}

} // namespace

bool paper_round_rule_holds(const VnConfig& c) {
  // a > √2.5·b/v_c  ⇔  a > 0 and 2a²v_c² > 5b²;  a > √10·b/(3v_c) + d_r  ⇔  a − d_r > 0
  // and 9(a − d_r)²v_c² > 10b².
  const long long a = c.delta - messaging(c), b = c.b, v = c.vc, after_rule = a - c.d_r;
  const bool travel = a > 0 && 2 * a * a * v * v > 5 * b * b;
  const bool restart = after_rule > 0 && 9 * after_rule * after_rule * v * v > 10 * b * b;
  return travel && restart;
}

double paper_round_bound(const VnConfig& c) {
  const double b = c.b, v = c.vc;
  return messaging(c) + std::max(std::sqrt(2.5) * b / v, std::sqrt(10.0) * b / (3 * v) + c.d_r);
}

std::string VnConfig::paper_round_bound_text() const {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", paper_round_bound(*this));
  return text;
}

int lattice_round_bound(const VnConfig& c) {
  const Lattice lattice = c.lattice();
  int farthest = lattice.b(); // within the zone (calctarget's lines 33–38)
  for (Point p = 0; p < lattice.points(); ++p)
    for (const RegionId g : lattice.nbrs(lattice.region_of(p)))
      farthest = std::max(farthest, lattice.distance(p, lattice.centre(g))); // line 31
  return messaging(c) + (farthest + c.vc - 1) / c.vc + c.d_r;
}

std::optional<std::string> invalid(const VnConfig& c) {
  if (c.rows < 1 || c.cols < 1 || c.rows * c.cols > 4)
    return "the grid must have 1 to 4 zones";
  if (c.b < 2 || c.b % 2 != 0 || c.b > 8)
    return "b must be even, 2..8";
  if (c.cns < 1 || c.cns > 3)
    return "cns must be 1..3";
  if (c.d_v < 1 || c.d_mmt < 0 || c.eps < 0 || c.d_r < 0 || c.vc < 1)
    return "need d_v >= 1, d_mmt >= 0, eps >= 0, d_r >= 0, vc >= 1";
  if (c.delta < 2 || c.delta > 64)
    return "delta must be 2..64";
  // Every message is then delivered before the round after next, which the round tags
  // (round_tags.hpp) need to stay exact.
  if (c.target_phase() >= c.delta)
    return "the target-trigger phase d_mmt + 3d_v + 2eps must fall inside the round (< delta)";
  if (c.k < 1)
    return "k must be >= 1";
  if (c.rho1 <= 0 || c.rho1 >= 1 || c.rho2 <= 0 || c.rho2 >= 1)
    return "rho1 and rho2 must lie in (0, 1)";
  return std::nullopt;
}

} // namespace vn_layer
