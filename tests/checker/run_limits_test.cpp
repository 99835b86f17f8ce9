// The limits checked between the steps of the pipeline (checker/run_limits.hpp).
#include <catch2/catch.hpp>

#include "checker/run_limits.hpp"

using namespace checker;

TEST_CASE("time_or_memory_exceeded: the time limit, then the memory held",
          "[checker][run_limits][limits]") {
  const Progress progress(false, "");
  std::size_t held = 100;
  const MemoryBudget budget(150, [&] { return held; });
  Limits limits;
  CHECK_FALSE(time_or_memory_exceeded(limits, progress, budget));
  limits.max_seconds = 1e-12;
  CHECK(time_or_memory_exceeded(limits, progress, budget) == StopReason::time_limit);
  held = 151;
  CHECK(time_or_memory_exceeded(limits, progress, budget) == StopReason::time_limit);
  limits.max_seconds = 0;
  CHECK(time_or_memory_exceeded(limits, progress, budget) == StopReason::memory_limit);
}

TEST_CASE("stop_after_level: a limit the workers met wins over the merge's reason",
          "[checker][run_limits][limits]") {
  const Progress progress(false, "");
  std::size_t held = 100;
  const MemoryBudget budget(150, [&] { return held; });
  const Limits limits;
  LevelSignals signals;
  CHECK_FALSE(stop_after_level(std::nullopt, signals, limits, progress, budget));
  CHECK(stop_after_level(StopReason::found, signals, limits, progress, budget) ==
        StopReason::found);
  held = 200; // checked only when nothing else stopped the run
  CHECK(stop_after_level(StopReason::state_limit, signals, limits, progress, budget) ==
        StopReason::state_limit);
  CHECK(stop_after_level(std::nullopt, signals, limits, progress, budget) ==
        StopReason::memory_limit);
  signals.out_of_memory = true;
  CHECK(stop_after_level(StopReason::found, signals, limits, progress, budget) ==
        StopReason::memory_limit);
  signals.out_of_time = true;
  CHECK(stop_after_level(StopReason::found, signals, limits, progress, budget) ==
        StopReason::time_limit);
}
