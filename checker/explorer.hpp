#pragma once
// Breadth-first exploration, level by level, in two phases per level:
//  1. expand (parallel): the frontier is cut into contiguous chunks, one per thread; each
//     thread generates the successors of its states, drops those already stored (the
//     store is only read in this phase) and keeps the rest as candidates;
//  2. merge (one thread): candidates are inserted chunk by chunk, in frontier order.
// Ids, parents, counts and the first target found are therefore the same for every
// thread count as for a plain sequential BFS, and traces are shortest in steps.

#include "checker/exploration.hpp"
#include "checker/hooks.hpp"
#include "checker/options.hpp"
#include "tioa/start_set.hpp"
#include "tioa/successors.hpp"

namespace checker {

Exploration explore(const tioa::SuccessorGenerator& generator, const tioa::StartSet& start,
                    const ExploreOptions& options, const ExploreHooks& hooks = {});

} // namespace checker
