#pragma once
// explore() (explorer.hpp) as the pipeline of its parts:
//   start insertion -> per level: expansion (parallel) -> merge -> limits -> next level.
// Included by explorer.hpp; explorer.cpp compiles it once for NoHooks and ExploreHooks.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "checker/expansion.hpp"
#include "checker/explorer.hpp"
#include "checker/frontier.hpp"
#include "checker/insertion.hpp"
#include "checker/memory_budget.hpp"
#include "checker/merge.hpp"
#include "checker/progress.hpp"
#include "checker/run_limits.hpp"
#include "checker/start_insertion.hpp"

namespace checker {

template <class Hooks>
Exploration explore(const tioa::SuccessorGenerator& generator, const tioa::StartSet& start,
                    const ExploreOptions& options, const Hooks& hooks) {
  const Limits& limits = options.limits;
  Exploration ex(generator.words());
  ex.threads = options.threads == 0 ? 1 : options.threads;
  Progress progress(options.progress, options.task.empty() ? "exploring" : options.task);
  std::vector<Worker> workers(ex.threads, Worker(generator.words()));
  Frontier frontier;
  // The memory limit counts the store, the parents, the edges, the frontiers and the
  // workers' buffers.
  MemoryBudget budget(limits.max_memory_bytes, [&] {
    std::size_t bytes = ex.memory_bytes() + frontier.bytes();
    for (const Worker& w : workers)
      bytes += w.bytes();
    return bytes;
  });
  Insertion insertion(ex, budget, limits.max_states, records_edges(hooks));

  std::optional<StopReason> stop =
      insert_start_states(start, ex, hooks, insertion, frontier.next(), [&](bool stopped) {
        std::optional<StopReason> reason;
        if (!stopped)
          reason = time_or_memory_exceeded(limits, progress, budget);
        progress.update(ex.store.size(), frontier.next().size(), 0);
        return reason;
      });
  frontier.advance();

  LevelSignals signals;
  while (!frontier.empty() && !stop) {
    const std::span<Worker> used(workers.data(),
                                 workers_for(frontier.current().size(), workers.size()));
    expand_level(used, hooks,
                 Level{generator, ex.store, frontier.current(), ex.depth, used.size(),
                       limits.max_seconds, progress, signals},
                 budget);
    const std::optional<StopReason> merged =
        merge_level(used, ex, insertion, budget, frontier.next());
    stop = stop_after_level(merged, signals, limits, progress, budget);
    budget.note(budget.held());
    frontier.advance();
    ++ex.depth;
    progress.update(ex.store.size(), frontier.current().size(), ex.depth);
  }
  if (stop)
    ex.stop = *stop;
  ex.peak_memory_bytes = budget.peak();
  ex.seconds = progress.elapsed();
  return ex;
}

} // namespace checker
