#pragma once
// Merge (one thread): a level's results enter the run in frontier order. First the
// workers' counts, stuck states and edges to known states; then their candidates, inserted
// one by one, worker after worker. So ids, parents and the first target found are those of
// a sequential breadth-first search, whatever the number of workers.

#include <optional>
#include <span>
#include <vector>

#include "checker/expansion.hpp"
#include "checker/exploration.hpp"
#include "checker/insertion.hpp"
#include "checker/memory_budget.hpp"

namespace checker {

// Merges the results of `workers` (in frontier order) into `ex`, the new states into
// `next`; why it stopped early, if it did (a target found, a state or memory limit). The
// counts go in whole, whatever stops the merge: they are then the same for every thread
// count.
std::optional<StopReason> merge_level(std::span<const Worker> workers, Exploration& ex,
                                      Insertion& insertion, MemoryBudget& budget,
                                      std::vector<StateId>& next);

} // namespace checker
