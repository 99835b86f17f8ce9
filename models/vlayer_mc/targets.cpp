#include "models/vlayer_mc/targets.hpp"

#include <algorithm>

#include "models/mc/spacing.hpp"

namespace vlayer_mc {

std::vector<mc::QuantisedLength> curve_q(const Lattice& lattice) {
  std::vector<mc::QuantisedLength> q(static_cast<std::size_t>(lattice.regions()), 0);
  for (int col = 0; col < lattice.cols(); ++col)
    q[static_cast<std::size_t>(col)] = lattice.b();
  return q;
}

bool on_curve(const Lattice& lattice, RegionId u, Point p) {
  if (u >= lattice.cols())
    return false;
  const int inf = u * lattice.b(), x = lattice.x_of(p);
  return lattice.y_of(p) == lattice.b() / 2 && x >= inf && x <= inf + lattice.b();
}

CurveEnds curve_ends(const Lattice& lattice, RegionId u, bool owned_ends) {
  const int inf = (u % lattice.cols()) * lattice.b();
  const bool last_column = u % lattice.cols() == lattice.cols() - 1;
  return {inf, inf + lattice.b() - (owned_ends && !last_column ? 1 : 0)};
}

std::vector<std::optional<Point>> compute_targets(const VlConfig& c, RegionId u,
                                                  const std::vector<std::optional<Point>>& reported,
                                                  const std::vector<int>& counts,
                                                  TargetBranches* branches) {
  TargetBranches taken;
  const Lattice lattice = c.lattice();
  const auto q = curve_q(lattice);
  const auto& nbrs = lattice.nbrs(u);
  std::vector<int> members; // dom M_u, by increasing id
  for (std::size_t p = 0; p < reported.size(); ++p)
    if (reported[p])
      members.push_back(static_cast<int>(p));

  mc::VnView view;
  view.h = static_cast<mc::RegionId>(u);
  view.y = static_cast<mc::RobotCount>(members.size());
  view.q = q[static_cast<std::size_t>(u)];
  for (std::size_t i = 0; i < nbrs.size(); ++i)
    view.neighbours.push_back(
        {static_cast<mc::RegionId>(nbrs[i]), counts.at(i), q[static_cast<std::size_t>(nbrs[i])]});
  const mc::AssignResult plan = mc::assign(view, mc::AssignParams(c.k, c.rho2));
  taken.assign = plan.branch;
  taken.reassigned = plan.total_sent() > 0;

  std::vector<std::optional<Point>> target(reported.size());
  std::size_t next = 0; // lowest ids first (line 11)
  for (std::size_t i = 0; i < nbrs.size(); ++i)
    for (mc::RobotCount sent = 0; sent < plan.sent[i]; ++sent)
      target[static_cast<std::size_t>(members[next++])] = lattice.centre(nbrs[i]); // line 31
  taken.to_centre = static_cast<int>(next);

  const bool on_curve_region = q[static_cast<std::size_t>(u)] != 0;
  const auto [inf, sup] = curve_ends(lattice, u, c.owned_ends);
  const int curve_y = lattice.b() / 2;
  std::vector<std::pair<int, int>> seq; // (x, id) of the staying robots on Γ_u (line 27)
  for (std::size_t i = next; i < members.size(); ++i) {
    const int p = members[i];
    const Point at = *reported[static_cast<std::size_t>(p)];
    const int x = lattice.x_of(at), y = lattice.y_of(at);
    if (!on_curve_region) {
      target[static_cast<std::size_t>(p)] = at; // Γ_u = ∅: keeps its position
      ++taken.stays;
    } else if (y != curve_y || x < inf || x > sup) {
      target[static_cast<std::size_t>(p)] =
          lattice.point(std::clamp(x, inf, sup), curve_y); // line 33
      ++taken.onto_curve;
    } else {
      seq.emplace_back(x, p);
    }
  }
  std::sort(seq.begin(), seq.end());
  std::vector<mc::Rational> sorted;
  for (const auto& [x, p] : seq)
    sorted.emplace_back(x);
  const auto moved = mc::spacing_step(sorted, mc::Rational(inf), mc::Rational(sup), c.rho1);
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const int x = mc::floor_of(moved[i]).convert_to<int>();
    target[static_cast<std::size_t>(seq[i].second)] = lattice.point(x, curve_y); // lines 35–38
  }
  // The first and the last of seq take lines 35–36 (one robot alone is the first).
  taken.to_end = static_cast<int>(std::min<std::size_t>(seq.size(), 2));
  taken.between = static_cast<int>(seq.size()) - taken.to_end;
  if (branches)
    *branches = taken;
  return target;
}

} // namespace vlayer_mc
