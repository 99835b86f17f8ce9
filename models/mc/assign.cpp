#include "models/mc/assign.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

namespace mc {

namespace {

using Wide = __int128;

// ⌊ρ2·x / divisor⌋ for x > 0, divisor > 0, exactly: in 128-bit integers when nothing
// overflows, else in arbitrary precision.
RobotCount damped_floor(const AssignParams& params, Wide x, Wide divisor) {
  if (params.small()) {
    Wide numerator = 0, denominator = 0;
    if (!__builtin_mul_overflow(x, static_cast<Wide>(params.rho2_numerator()), &numerator) &&
        !__builtin_mul_overflow(divisor, static_cast<Wide>(params.rho2_denominator()),
                                &denominator))
      return static_cast<RobotCount>(numerator / denominator); // both > 0: / is ⌊ ⌋
  }
  auto big = [](Wide value) {
    // value > 0 and < 2^127: two 64-bit halves.
    const auto high = static_cast<std::uint64_t>(value >> 64);
    const auto low = static_cast<std::uint64_t>(value);
    return (BigInteger(high) << 64) + BigInteger(low);
  };
  const BigInteger result = floor_of(params.rho2() * Rational(big(x), big(divisor)));
  return static_cast<RobotCount>(result); // <= x <= 10^18 (the bounds of check_view)
}

void check_region(RegionId id, RobotCount y, QuantisedLength q) {
  if (y < 0 || y > max_robots)
    throw std::invalid_argument("assign: region " + std::to_string(id) + " has " +
                                std::to_string(y) + " robots (allowed: 0.." +
                                std::to_string(max_robots) + ")");
  if (q < 0 || q > max_quantised_length)
    throw std::invalid_argument("assign: region " + std::to_string(id) +
                                " has q = " + std::to_string(q) + " (allowed: 0.." +
                                std::to_string(max_quantised_length) + ")");
}

void check_view(const VnView& view) {
  check_region(view.h, view.y, view.q);
  for (const auto& g : view.neighbours)
    check_region(g.id, g.y, g.q);
}

// The branch of lines 6, 7, 13 and 19, lower (lines 8 / 14, in id order; In for the
// boundary) as neighbour indices, and `ideal` for each neighbour.
struct Plan {
  AssignBranch branch = AssignBranch::keep;
  std::vector<std::size_t> lower;
  std::vector<RobotCount> ideal;
};

Plan plan(const VnView& view, const AssignParams& params) {
  check_view(view);
  Plan p;
  p.ideal.assign(view.neighbours.size(), 0);
  const RobotCount e = params.k();
  if (view.y <= e) // line 6
    return p;
  const Wide yh = view.y, qh = view.q;
  std::vector<std::size_t> in; // In = {g ∈ Nbrs : q_g ≠ 0} (Fig. 6 line 10)
  for (std::size_t i = 0; i < view.neighbours.size(); ++i)
    if (view.neighbours[i].q != 0)
      in.push_back(i);

  if (view.q != 0) { // line 7
    p.branch = AssignBranch::on_curve;
    // line 8: (q_g/q_h)·y(h) > y(g)  ⇔  q_g·y(h) > y(g)·q_h  (q_h > 0)
    for (std::size_t i : in) {
      const auto& g = view.neighbours[i];
      if (Wide(g.q) * yh > Wide(g.y) * qh)
        p.lower.push_back(i);
    }
    // line 10: ρ2·[(q_g/q_h)·y(h) − y(g)] / 2(|lower|+1)
    //        = ρ2·(q_g·y(h) − q_h·y(g)) / (q_h·2(|lower|+1))
    const Wide divisor = qh * 2 * (Wide(p.lower.size()) + 1);
    for (std::size_t i : p.lower) {
      const auto& g = view.neighbours[i];
      p.ideal[i] = damped_floor(params, Wide(g.q) * yh - Wide(g.y) * qh, divisor);
    }
  } else if (in.empty()) { // line 13
    p.branch = AssignBranch::no_curve_neighbour;
    for (std::size_t i = 0; i < view.neighbours.size(); ++i) // line 14
      if (yh > view.neighbours[i].y)
        p.lower.push_back(i);
    // line 16: ρ2·[y(h) − y(g)] / 2(|lower|+1)
    const Wide divisor = 2 * (Wide(p.lower.size()) + 1);
    for (std::size_t i : p.lower)
      p.ideal[i] = damped_floor(params, yh - view.neighbours[i].y, divisor);
  } else { // line 19
    p.branch = AssignBranch::boundary;
    p.lower = in;
    const RobotCount ra = (view.y - e) / static_cast<RobotCount>(in.size()); // line 20
    for (std::size_t i : in)
      p.ideal[i] = ra;
  }
  return p;
}

// Lines 9–12 / 15–18 (or 21–22) with lower visited in `order` (neighbour indices).
AssignResult run(const VnView& view, const AssignParams& params, const Plan& p,
                 const std::vector<std::size_t>& order) {
  AssignResult result;
  result.branch = p.branch;
  result.ideal = p.ideal;
  result.sent.assign(view.neighbours.size(), 0);
  RobotCount n = view.y; // line 4
  for (std::size_t i : order) {
    result.lower.push_back(view.neighbours[i].id);
    if (p.branch == AssignBranch::boundary) { // lines 21–22: no cap, no n
      result.sent[i] = p.ideal[i];
      continue;
    }
    const RobotCount ra = std::min(p.ideal[i], n - params.k()); // lines 10 / 16
    result.sent[i] = ra;                                        // lines 11 / 17
    n -= ra;                                                    // lines 12 / 18
  }
  return result;
}

} // namespace

AssignParams::AssignParams(RobotCount k, Rational rho2) : k_(k), rho2_(std::move(rho2)) {
  if (k_ < 1)
    throw std::invalid_argument("k (the safe number of robots, e in seed 002) must be >= 1, not " +
                                std::to_string(k_));
  if (rho2_ <= 0 || rho2_ >= 1)
    throw std::invalid_argument("rho2 must be in (0, 1), not " + mc::to_string(rho2_));
  const BigInteger& numerator = boost::multiprecision::numerator(rho2_);
  const BigInteger& denominator = boost::multiprecision::denominator(rho2_);
  const BigInteger limit = std::numeric_limits<std::int64_t>::max();
  small_ = numerator <= limit && denominator <= limit;
  if (small_) {
    numerator_ = static_cast<std::int64_t>(numerator);
    denominator_ = static_cast<std::int64_t>(denominator);
  }
}

std::string to_string(AssignBranch branch) {
  switch (branch) {
  case AssignBranch::keep:
    return "keep";
  case AssignBranch::on_curve:
    return "on-curve";
  case AssignBranch::no_curve_neighbour:
    return "no-curve-neighbour";
  case AssignBranch::boundary:
    return "boundary";
  }
  return "?";
}

RobotCount AssignResult::total_sent() const {
  RobotCount total = 0;
  for (RobotCount s : sent)
    total += s;
  return total;
}

VnView vn_view(const GridTiling& grid, RegionId h, std::span<const RobotCount> y,
               std::span<const QuantisedLength> q) {
  if (y.size() != grid.size() || q.size() != grid.size())
    throw std::invalid_argument("vn_view: " + std::to_string(y.size()) + " counts and " +
                                std::to_string(q.size()) + " curve lengths for " +
                                std::to_string(grid.size()) + " regions");
  if (h >= grid.size())
    throw std::invalid_argument("vn_view: no region " + std::to_string(h));
  VnView view;
  view.h = h;
  view.y = y[h];
  view.q = q[h];
  for (RegionId g : grid.nbrs(h))
    view.neighbours.push_back({g, y[g], q[g]});
  check_view(view);
  return view;
}

AssignResult assign(const VnView& view, const AssignParams& params) {
  const Plan p = plan(view, params);
  return run(view, params, p, p.lower);
}

AssignResult assign(const VnView& view, const AssignParams& params,
                    std::span<const RegionId> order) {
  const Plan p = plan(view, params);
  if (p.branch == AssignBranch::keep || p.branch == AssignBranch::boundary)
    return run(view, params, p, p.lower);
  std::vector<std::size_t> indices;
  for (RegionId id : order) {
    const auto it = std::find_if(p.lower.begin(), p.lower.end(),
                                 [&](std::size_t i) { return view.neighbours[i].id == id; });
    if (it == p.lower.end() || std::find(indices.begin(), indices.end(), *it) != indices.end())
      throw std::invalid_argument("assign: the order is not a permutation of lower (region " +
                                  std::to_string(id) + ")");
    indices.push_back(*it);
  }
  if (indices.size() != p.lower.size())
    throw std::invalid_argument("assign: the order has " + std::to_string(indices.size()) +
                                " regions, lower has " + std::to_string(p.lower.size()));
  return run(view, params, p, indices);
}

std::vector<AssignResult> assign_every_order(const VnView& view, const AssignParams& params) {
  const Plan p = plan(view, params);
  if (p.branch == AssignBranch::keep || p.branch == AssignBranch::boundary)
    return {run(view, params, p, p.lower)};
  // In any order, the neighbours before the first one where the cap n − e binds get their
  // ideal, that one gets what is left, the later ones 0. So an outcome is a set S of
  // neighbours served in full, with Σ_S ideal < y(h) − e, and the neighbour g where the
  // cap binds, with Σ_S ideal + ideal_g >= y(h) − e: realised by the order S, g, the rest.
  // When Σ_lower ideal <= y(h) − e the cap never binds and the order does not matter.
  const RobotCount budget = view.y - params.k();
  std::vector<std::size_t> candidates; // those with ideal > 0: the others always get 0
  RobotCount total = 0;
  for (std::size_t i : p.lower)
    if (p.ideal[i] > 0) {
      candidates.push_back(i);
      total += p.ideal[i];
    }
  if (total <= budget)
    return {run(view, params, p, p.lower)};

  std::map<std::vector<RobotCount>, AssignResult> outcomes;
  const std::size_t c = candidates.size(); // <= 8
  for (std::uint32_t subset = 0; subset < (1u << c); ++subset) {
    RobotCount served = 0;
    std::vector<std::size_t> order;
    for (std::size_t j = 0; j < c; ++j)
      if (subset & (1u << j)) {
        served += p.ideal[candidates[j]];
        order.push_back(candidates[j]);
      }
    if (served >= budget)
      continue;
    for (std::size_t j = 0; j < c; ++j) {
      if ((subset & (1u << j)) || served + p.ideal[candidates[j]] < budget)
        continue;
      std::vector<std::size_t> full = order;
      full.push_back(candidates[j]);
      for (std::size_t i : p.lower)
        if (std::find(full.begin(), full.end(), i) == full.end())
          full.push_back(i);
      AssignResult result = run(view, params, p, full);
      outcomes.try_emplace(result.sent, std::move(result));
    }
  }
  std::vector<AssignResult> out;
  for (auto& [sent, result] : outcomes)
    out.push_back(std::move(result));
  return out;
}

} // namespace mc
