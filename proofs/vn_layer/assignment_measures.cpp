#include "proofs/vn_layer/assignment_measures.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "models/mc/spacing.hpp"
#include "models/vlayer_mc/targets.hpp"

namespace vn_layer {

mc::Rational density_spread(const std::vector<int>& counts,
                            const std::vector<mc::QuantisedLength>& q) {
  // The densest and the sparsest zone of In, compared by cross-multiplying (small integers).
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::size_t low = none, high = none;
  const auto less = [&](std::size_t a, std::size_t b) {
    return static_cast<std::int64_t>(counts[a]) * q[b] <
           static_cast<std::int64_t>(counts[b]) * q[a];
  };
  for (std::size_t h = 0; h < counts.size(); ++h) {
    if (counts[h] < 1 || q[h] == 0)
      continue;
    if (low == none || less(h, low))
      low = h;
    if (high == none || less(high, h))
      high = h;
  }
  if (low == none)
    return mc::Rational(0);
  return mc::Rational(counts[high], q[high]) - mc::Rational(counts[low], q[low]);
}

mc::QuantisedLength q_min_of(const std::vector<mc::QuantisedLength>& q) {
  mc::QuantisedLength q_min = 0;
  for (const mc::QuantisedLength length : q)
    if (length != 0 && (q_min == 0 || length < q_min))
      q_min = length;
  return q_min;
}

mc::Rational proportionality_bound(const VnConfig& c) {
  const int m = std::max(c.rows, c.cols);
  return mc::Rational(10 * (2 * m - 1)) /
         (mc::Rational(q_min_of(vlayer_mc::curve_q(c.lattice()))) * c.rho2);
}

SpacingGap spacing_gap(const VnConfig& c, const Lattice& lattice, const std::vector<int>& points) {
  const auto q = vlayer_mc::curve_q(lattice);
  std::vector<std::vector<int>> xs(static_cast<std::size_t>(lattice.regions()));
  for (const int p : points)
    if (p >= 0)
      xs[static_cast<std::size_t>(lattice.region_of(p))].push_back(lattice.x_of(p));
  SpacingGap worst;
  for (RegionId h = 0; h < lattice.regions(); ++h) {
    std::vector<int>& x = xs[static_cast<std::size_t>(h)];
    if (q[static_cast<std::size_t>(h)] == 0 || x.size() < 2)
      continue;
    std::sort(x.begin(), x.end());
    const auto [inf, sup] = vlayer_mc::curve_ends(lattice, h, c.owned_ends);
    const std::vector<mc::Rational> even =
        mc::even_spacing(x.size(), mc::Rational(inf), mc::Rational(sup));
    mc::Rational distance(0);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const mc::Rational gap = mc::Rational(x[i]) - even[i];
      distance = std::max(distance, mc::Rational(gap < 0 ? -gap : gap));
    }
    if (distance > worst.distance) {
      std::string at, even_at;
      for (std::size_t i = 0; i < x.size(); ++i) {
        at += (i ? ", " : "") + std::to_string(x[i]);
        even_at += (i ? ", " : "") + mc::to_string(even[i]);
      }
      worst = {distance, "zone " + std::to_string(h) + ": CNs at x = " + at +
                             ", evenly spaced at x = " + even_at};
    }
  }
  return worst;
}

} // namespace vn_layer
