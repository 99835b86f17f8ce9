#include "checker/run_limits.hpp"

namespace checker {

std::optional<StopReason> time_or_memory_exceeded(const Limits& limits, const Progress& progress,
                                                  const MemoryBudget& budget) {
  if (interrupted())
    return StopReason::interrupted;
  if (limits.out_of_time(progress.elapsed()))
    return StopReason::time_limit;
  if (budget.exceeded() || resident_over_limit(limits))
    return StopReason::memory_limit;
  return std::nullopt;
}

std::optional<StopReason> property_limit_reached(const Limits& limits) {
  if (interrupted())
    return StopReason::interrupted;
  if (limits.deadline && std::chrono::steady_clock::now() > *limits.deadline)
    return StopReason::time_limit;
  if (resident_over_limit(limits))
    return StopReason::memory_limit;
  return std::nullopt;
}

std::optional<StopReason> stop_after_level(std::optional<StopReason> ended,
                                           const LevelSignals& signals, const Limits& limits,
                                           const Progress& progress, const MemoryBudget& budget) {
  if (interrupted())
    return StopReason::interrupted;
  if (signals.out_of_time)
    return StopReason::time_limit;
  if (signals.out_of_memory)
    return StopReason::memory_limit;
  if (ended)
    return ended;
  return time_or_memory_exceeded(limits, progress, budget);
}

} // namespace checker
