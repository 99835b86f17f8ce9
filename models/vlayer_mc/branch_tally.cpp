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

std::vector<std::int32_t> encode(const std::vector<BranchRecord>& records) {
  std::vector<std::int32_t> words;
  for (const BranchRecord& r : records) {
    words.push_back(r.u);
    words.push_back(static_cast<std::int32_t>(r.key.size()));
    words.insert(words.end(), r.key.begin(), r.key.end());
    const TargetBranches& b = r.branches;
    words.insert(words.end(), {static_cast<std::int32_t>(b.assign), b.reassigned ? 1 : 0,
                               b.to_centre, b.onto_curve, b.to_end, b.between, b.stays});
  }
  return words;
}

std::vector<BranchRecord> decode(const std::vector<std::int32_t>& words) {
  constexpr std::size_t branch_words = 7;
  std::vector<BranchRecord> records;
  for (std::size_t at = 0; at + 2 <= words.size();) {
    BranchRecord r;
    r.u = words[at];
    const auto size = static_cast<std::size_t>(words[at + 1]);
    if (at + 2 + size + branch_words > words.size())
      break; // cut short: never from encode
    const auto first = words.begin() + static_cast<std::ptrdiff_t>(at + 2);
    r.key.assign(first, first + static_cast<std::ptrdiff_t>(size));
    const std::int32_t* b = words.data() + at + 2 + size;
    r.branches = {static_cast<mc::AssignBranch>(b[0]), b[1] != 0, b[2], b[3], b[4], b[5], b[6]};
    records.push_back(std::move(r));
    at += 2 + size + branch_words;
  }
  return records;
}

} // namespace vlayer_mc
