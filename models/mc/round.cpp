#include "models/mc/round.hpp"

#include <algorithm>
#include <cassert>
#include <optional>
#include <string>
#include <tuple>

namespace mc {

namespace {

const McParams& checked(const McParams& params) {
  if (params.rho1 <= 0 || params.rho1 >= 1)
    throw std::invalid_argument("rho1 must be in (0, 1), not " + to_string(params.rho1));
  return params; // k and rho2: AssignParams checks them
}

} // namespace

RobotCount total(const Counts& counts) {
  RobotCount sum = 0;
  for (RobotCount c : counts)
    sum += c;
  return sum;
}

// ---- Flow

RobotCount Flow::at(RegionId from, RegionId to) const {
  const auto it = std::lower_bound(transfers.begin(), transfers.end(), Transfer{from, to, 0},
                                   [](const Transfer& a, const Transfer& b) {
                                     return std::tie(a.from, a.to) < std::tie(b.from, b.to);
                                   });
  return it != transfers.end() && it->from == from && it->to == to ? it->robots : 0;
}

RobotCount Flow::sent_by(RegionId h) const {
  RobotCount sum = 0;
  for (const auto& t : transfers)
    if (t.from == h)
      sum += t.robots;
  return sum;
}

RobotCount Flow::received_by(RegionId h) const {
  RobotCount sum = 0;
  for (const auto& t : transfers)
    if (t.to == h)
      sum += t.robots;
  return sum;
}

Counts Flow::apply(const Counts& counts) const {
  Counts out = counts;
  for (const auto& t : transfers) {
    out.at(t.from) -= t.robots;
    out.at(t.to) += t.robots;
  }
  return out;
}

std::vector<std::vector<RobotCount>> Flow::dense(std::size_t regions) const {
  std::vector<std::vector<RobotCount>> matrix(regions, std::vector<RobotCount>(regions, 0));
  for (const auto& t : transfers)
    matrix.at(t.from).at(t.to) = t.robots;
  return matrix;
}

// ---- RoundSystem

RoundSystem::RoundSystem(GridTiling grid, std::vector<QuantisedLength> q, McParams params)
    : grid_(std::move(grid)), q_(std::move(q)), params_(checked(params)),
      assign_params_(params_.k, params_.rho2) {
  if (q_.size() != grid_.size())
    throw std::invalid_argument(std::to_string(q_.size()) + " curve lengths q for " +
                                std::to_string(grid_.size()) + " regions");
  for (std::size_t u = 0; u < q_.size(); ++u)
    if (q_[u] < 0 || q_[u] > max_quantised_length)
      throw std::invalid_argument("q of region " + std::to_string(u) + " is " +
                                  std::to_string(q_[u]) + " (allowed: 0.." +
                                  std::to_string(max_quantised_length) + " units of sigma)");
}

void RoundSystem::check_counts(const Counts& counts) const {
  if (counts.size() != grid_.size())
    throw std::invalid_argument(std::to_string(counts.size()) + " robot counts for " +
                                std::to_string(grid_.size()) + " regions");
  RobotCount sum = 0;
  for (std::size_t u = 0; u < counts.size(); ++u) {
    if (counts[u] < 0 || counts[u] > max_robots)
      throw std::invalid_argument("region " + std::to_string(u) + " has " +
                                  std::to_string(counts[u]) + " robots (allowed: 0.." +
                                  std::to_string(max_robots) + ")");
    sum += counts[u];
    if (sum > max_robots)
      throw std::invalid_argument("more than " + std::to_string(max_robots) + " robots in all");
  }
}

VnView RoundSystem::view(const Counts& counts, RegionId h) const {
  return vn_view(grid_, h, counts, q_);
}

namespace {

void add_transfers(Flow& flow, const VnView& view, const AssignResult& result) {
  for (std::size_t i = 0; i < view.neighbours.size(); ++i)
    if (result.sent[i] > 0)
      flow.transfers.push_back({view.h, view.neighbours[i].id, result.sent[i]});
}

} // namespace

Flow RoundSystem::flow(const Counts& counts) const {
  check_counts(counts);
  Flow flow;
  // Regions in increasing id, neighbours in increasing id: transfers come out sorted.
  for (RegionId h = 0; h < grid_.size(); ++h) {
    if (counts[h] <= params_.k) // line 6 (also: a region without robots has no VN)
      continue;
    const VnView v = view(counts, h);
    add_transfers(flow, v, assign(v, assign_params_));
  }
  return flow;
}

Counts RoundSystem::next(const Counts& counts) const {
  return flow(counts).apply(counts);
}

std::vector<Flow> RoundSystem::all_flows(const Counts& counts, std::size_t limit) const {
  check_counts(counts);
  std::vector<VnView> views;
  std::vector<std::vector<AssignResult>> outcomes;
  std::size_t combinations = 1;
  for (RegionId h = 0; h < grid_.size(); ++h) {
    if (counts[h] <= params_.k)
      continue;
    views.push_back(view(counts, h));
    outcomes.push_back(assign_every_order(views.back(), assign_params_));
    const std::size_t options = outcomes.back().size();
    if (combinations > limit / options) // combinations·options > limit, without overflow
      throw TooManyOutcomes("one round from these counts has more than " + std::to_string(limit) +
                            " combinations of per-region assign outcomes (over the orders of "
                            "each lower set)");
    combinations *= options;
  }
  // Every combination, as an odometer over the per-region outcomes (each sorted): the
  // flows come out distinct (regions differ in what they send) and sorted.
  std::vector<Flow> flows;
  flows.reserve(combinations);
  std::vector<std::size_t> digit(views.size(), 0);
  for (std::size_t made = 0; made < combinations; ++made) {
    Flow flow;
    for (std::size_t r = 0; r < views.size(); ++r)
      add_transfers(flow, views[r], outcomes[r][digit[r]]);
    flows.push_back(std::move(flow));
    for (std::size_t r = views.size(); r-- > 0;) {
      if (++digit[r] < outcomes[r].size())
        break;
      digit[r] = 0;
    }
  }
  std::sort(flows.begin(), flows.end());
  return flows;
}

std::vector<Counts> RoundSystem::all_next(const Counts& counts, std::size_t limit) const {
  std::vector<Counts> out;
  for (const Flow& flow : all_flows(counts, limit))
    out.push_back(flow.apply(counts));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<RegionId> RoundSystem::in_regions(const Counts& counts) const {
  check_counts(counts);
  std::vector<RegionId> out;
  for (RegionId h = 0; h < grid_.size(); ++h)
    if (counts[h] >= 1 && q_[h] != 0)
      out.push_back(h);
  return out;
}

std::vector<RegionId> RoundSystem::out_regions(const Counts& counts) const {
  check_counts(counts);
  std::vector<RegionId> out;
  for (RegionId h = 0; h < grid_.size(); ++h)
    if (counts[h] >= 1 && q_[h] == 0)
      out.push_back(h);
  return out;
}

FixpointRun RoundSystem::run_to_fixpoint(const Counts& start, const RunOptions& options) const {
  check_counts(start);
  FixpointRun run;
  Counts current = start;
  if (options.keep_history)
    run.rounds.push_back(current);
  // The last round t in which a robot left or joined a region of Out(t) (of In(t)).
  std::optional<std::size_t> last_out, last_in;
  for (std::size_t t = 0;; ++t) {
    Flow f = flow(current);
    Counts after = f.apply(current);
    if (after == current) {
      // Every transfer goes to a strictly "lower" region (Out → Out: fewer robots; Out →
      // In: the boundary; In → In: lower density y/q; never In → Out), so no robot moves
      // when no count changes.
      assert(f.empty());
      run.fixpoint_round = t;
      break;
    }
    if (t == options.max_rounds)
      throw RoundLimitReached("no fixed point within " + std::to_string(options.max_rounds) +
                                  " rounds (the counts still change in round " + std::to_string(t) +
                                  ")",
                              t);
    if (options.stop && options.stop())
      throw RoundLimitReached(
          options.stop_reason + " in round " + std::to_string(t) + ", before the fixed point", t);
    auto active = [&](RegionId h) { return current[h] >= 1; };
    for (const Transfer& move : f.transfers)
      for (RegionId h : {move.from, move.to})
        if (active(h))
          (q_[h] == 0 ? last_out : last_in) = t;
    if (options.keep_history) {
      run.flows.push_back(std::move(f));
      run.rounds.push_back(after);
    }
    current = std::move(after);
  }
  if (!options.keep_history)
    run.rounds.push_back(current);
  run.t_out = last_out ? *last_out + 1 : 0;
  run.t_stab = std::max(run.t_out, last_in ? *last_in + 1 : 0);
  return run;
}

} // namespace mc
