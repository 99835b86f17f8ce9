#pragma once
// compute_targets (targets.hpp) remembered: VN_u's compute step asks for the targets of
// the same reports and counts in many states (issue 14: the model must not allocate per
// state), and compute_targets builds the lattice, the assign parameters and rationals on
// every call. A memo holds, per distinct input, the targets as lattice points (none for
// a robot with no target), computed once; threads share it (lookups under a shared lock,
// a miss computes outside the lock and inserts under an exclusive one). With the config's
// branch tally, each lookup counts its computation's branches of Fig. 7 there, once per
// epoch.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "models/vlayer_mc/branch_tally.hpp"
#include "models/vlayer_mc/config.hpp"

namespace vlayer_mc {

class TargetMemo {
public:
  static constexpr std::int32_t none = -1; // ⊥: not reported, or no target

  TargetMemo(const VlConfig& config, RegionId u);

  // heard[p]: M_u(p) or none, for every robot; counts[i]: V_u(nbrs(u)[i]). Returns the
  // target of every robot (none for those not in dom M_u), valid for the memo's life.
  // `key` is the caller's buffer (robots + neighbours entries), reused from call to call.
  const std::int32_t* targets(std::vector<std::int32_t>& key) const;

  std::size_t robots() const { return robots_; }
  std::size_t neighbours() const { return neighbours_; }

private:
  struct Hash {
    std::size_t operator()(const std::vector<std::int32_t>& key) const;
  };
  struct Entry {
    Entry(std::vector<std::int32_t> t, const TargetBranches& b)
        : targets(std::move(t)), branches(b) {}
    std::vector<std::int32_t> targets;
    TargetBranches branches;
    mutable std::atomic<std::uint32_t> counted{0}; // the tally's epoch it was last counted in
  };
  // The entry's targets, counted in the tally when there is one.
  const std::int32_t* counted(const std::vector<std::int32_t>& key, const Entry& entry) const;

  VlConfig config_;
  RegionId u_;
  std::size_t robots_, neighbours_;
  mutable std::shared_mutex mutex_;
  // Node-based: a value stays where it is while others are inserted.
  mutable std::unordered_map<std::vector<std::int32_t>, Entry, Hash> table_;
};

} // namespace vlayer_mc
