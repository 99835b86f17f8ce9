#include "models/vlayer_mc/branch_tally.hpp"

#include <algorithm>

namespace vlayer_mc {

namespace {

// Adds one computation's branches to `n`.
void add_target_branches(const TargetBranches& b, BranchCounts& n) {
  ++n.computations;
  if (b.reassigned)
    ++(b.assign == mc::AssignBranch::on_curve             ? n.on_curve
       : b.assign == mc::AssignBranch::no_curve_neighbour ? n.no_curve_neighbour
                                                          : n.boundary);
  n.to_centre += static_cast<std::uint64_t>(b.to_centre);
  n.onto_curve += static_cast<std::uint64_t>(b.onto_curve);
  n.to_end += static_cast<std::uint64_t>(b.to_end);
  n.between += static_cast<std::uint64_t>(b.between);
  n.stays += static_cast<std::uint64_t>(b.stays);
}

} // namespace

void BranchTally::start_epoch() {
  const std::lock_guard lock(mutex_);
  records_.clear();
  epoch_.fetch_add(1, std::memory_order_acq_rel);
}

void BranchTally::count(int u, const std::vector<std::int32_t>& key, const TargetBranches& b,
                        std::atomic<std::uint32_t>& seen) {
  const std::uint32_t now = epoch_.load(std::memory_order_acquire);
  std::uint32_t was = seen.load(std::memory_order_relaxed);
  do {
    if (was == now)
      return; // recorded in this epoch already
  } while (!seen.compare_exchange_weak(was, now, std::memory_order_relaxed));
  const std::lock_guard lock(mutex_); // once per computation and epoch: rare
  records_.push_back({u, key, b});
}

BranchCounts BranchTally::counts() const {
  return sum_distinct(records());
}

std::vector<BranchRecord> BranchTally::records() const {
  const std::lock_guard lock(mutex_);
  return records_;
}

BranchCounts sum_distinct(std::vector<BranchRecord> records) {
  const auto before = [](const BranchRecord& a, const BranchRecord& b) {
    return a.u != b.u ? a.u < b.u : a.key < b.key;
  };
  std::sort(records.begin(), records.end(), before);
  BranchCounts n;
  for (std::size_t i = 0; i < records.size(); ++i)
    if (i == 0 || before(records[i - 1], records[i]))
      add_target_branches(records[i].branches, n);
  return n;
}

} // namespace vlayer_mc
