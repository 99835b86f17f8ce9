#include "models/vlayer_mc/target_memo.hpp"

#include <optional>

#include "models/vlayer_mc/targets.hpp"

namespace vlayer_mc {

TargetMemo::TargetMemo(const VlConfig& config, RegionId u)
    : config_(config), u_(u), robots_(static_cast<std::size_t>(config.robots)),
      neighbours_(config.lattice().nbrs(u).size()) {}

std::size_t TargetMemo::Hash::operator()(const std::vector<std::int32_t>& key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const std::int32_t v : key) {
    h ^= static_cast<std::uint32_t>(v);
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return static_cast<std::size_t>(h);
}

const std::int32_t* TargetMemo::targets(std::vector<std::int32_t>& key) const {
  {
    const std::shared_lock lock(mutex_);
    const auto found = table_.find(key);
    if (found != table_.end())
      return counted(found->first, found->second);
  }
  std::vector<std::optional<Point>> heard(robots_);
  for (std::size_t p = 0; p < robots_; ++p)
    if (key[p] != none)
      heard[p] = key[p];
  const std::vector<int> counts(key.begin() + static_cast<std::ptrdiff_t>(robots_), key.end());
  TargetBranches branches;
  const std::vector<std::optional<Point>> computed =
      compute_targets(config_, u_, heard, counts, &branches);
  std::vector<std::int32_t> value(robots_, none);
  for (std::size_t p = 0; p < robots_; ++p)
    if (computed[p])
      value[p] = *computed[p];
  const std::unique_lock lock(mutex_);
  // Another thread may have won; the entry it made is the one counted.
  const auto [at, inserted] = table_.try_emplace(key, std::move(value), branches);
  return counted(at->first, at->second);
}

const std::int32_t* TargetMemo::counted(const std::vector<std::int32_t>& key,
                                        const Entry& entry) const {
  if (config_.branch_tally)
    config_.branch_tally->count(u_, key, entry.branches, entry.counted);
  return entry.targets.data();
}

} // namespace vlayer_mc
