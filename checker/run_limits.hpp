#pragma once
// The limits a run checks between the steps of the pipeline. The state limit is checked
// at every insertion (insertion.hpp, expansion.hpp) and the memory limit at every growth
// (memory_budget.hpp); the workers check time every 1024 states and the property's resident
// memory every 16384 (expansion.hpp); here, time and the memory held are checked after each
// batch of start states and after each level, and the workers' reasons to stop early are
// weighed.

#include <atomic>
#include <cstdint>
#include <optional>

#include "checker/interrupt.hpp"
#include "checker/memory_budget.hpp"
#include "checker/options.hpp"
#include "checker/progress.hpp"

namespace checker {

// Why the workers of a level stopped before the end of the frontier; set from any worker.
struct LevelSignals {
  std::atomic<bool> out_of_time{false};
  std::atomic<bool> out_of_memory{false};
  std::atomic<bool> state_limit{false}; // a new state met the state limit
};

// A stop requested from outside, the time limit, then the memory held (by the run, or by
// the property as its resident memory shows).
std::optional<StopReason> time_or_memory_exceeded(const Limits& limits, const Progress& progress,
                                                  const MemoryBudget& budget);

// Whether a property must stop now, between its explorations: a stop requested from
// outside, its deadline passed (Limits::deadline; max_seconds alone bounds each exploration),
// or its resident memory over the limit. For the loops a check runs over the states an
// exploration found or over a family it builds, which no exploration bounds.
std::optional<StopReason> property_limit_reached(const Limits& limits);

// property_limit_reached for such a loop, asked at items 0, 4096, 8192, ... (the clock and
// /proc/self/statm cost too much per state); the first stop it sees stays.
class PropertyLimitPoll {
public:
  explicit PropertyLimitPoll(const Limits& limits) : limits_(&limits) {}
  // Whether the loop must stop before item `done`.
  bool reached(std::uint64_t done) {
    if (!stopped_ && (done & 4095) == 0)
      if (const std::optional<StopReason> stop = property_limit_reached(*limits_)) {
        stopped_ = true;
        reason_ = *stop;
      }
    return stopped_;
  }
  bool stopped() const { return stopped_; }
  StopReason reason() const { return reason_; } // when stopped()

private:
  const Limits* limits_;
  bool stopped_ = false;
  StopReason reason_ = StopReason::finished;
};

// Why the run stops after a level whose end (level_end.hpp) gave `ended` (none: the level
// went in whole); none when it goes on. A limit the workers met wins over the level end's
// reason; time and memory are checked only when nothing stopped.
std::optional<StopReason> stop_after_level(std::optional<StopReason> ended,
                                           const LevelSignals& signals, const Limits& limits,
                                           const Progress& progress, const MemoryBudget& budget);

} // namespace checker
