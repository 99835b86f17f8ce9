#pragma once
// Breadth-first exploration, level by level; a level is a range of ids. The pipeline
// (explorer_impl.hpp), one part per header:
//   start_insertion.hpp  level 0: the start set, canonicalised, inserted in batches
//                        through insertion.hpp (the state and memory limits);
//   expansion.hpp        (parallel) the frontier cut into chunks that the workers take
//                        in order; each generates the successors of its states and inserts
//                        them into the store itself, concurrently, each new state keeping
//                        the step that found it first (discovery.hpp); the store grows
//                        while the workers wait at growth_gate.hpp;
//   level_end.hpp        counts, stuck states and edges (the workers' merged in frontier
//                        order); the new states renumbered in the order of their first
//                        steps (the store's share on every worker thread), their parents;
//                        the first target found;
//   run_limits.hpp       time and memory after each level;
// with memory_budget.hpp (the memory limit at every growth), state_store.hpp (the visited
// states) and trace.hpp (paths rebuilt from parents). Ids, parents, counts, edges and the
// first target found are therefore the same for every thread count as for a plain
// sequential BFS, and traces are shortest in steps. A level that meets the state limit
// with several workers is done again by one (which states fit depends on their race).
//
// Hooks (hooks.hpp) are a template parameter: those a Hooks type lacks are not compiled
// in. explore() for NoHooks and for ExploreHooks (std::function members, chosen at run
// time) is compiled once, in explorer.cpp.

#include "checker/exploration.hpp"
#include "checker/hooks.hpp"
#include "checker/options.hpp"
#include "checker/zero_time_reduction.hpp"
#include "tioa/start_set.hpp"
#include "tioa/successors.hpp"

namespace checker {

// With a `reduction`, states where time cannot pass are expanded by its stubborn sets.
template <class Hooks = NoHooks>
Exploration explore(const tioa::SuccessorGenerator& generator, const tioa::StartSet& start,
                    const ExploreOptions& options, const Hooks& hooks = {},
                    const ZeroTimeReduction* reduction = nullptr);

} // namespace checker

#include "checker/explorer_impl.hpp"

namespace checker {

extern template Exploration explore<NoHooks>(const tioa::SuccessorGenerator&, const tioa::StartSet&,
                                             const ExploreOptions&, const NoHooks&,
                                             const ZeroTimeReduction*);
extern template Exploration explore<ExploreHooks>(const tioa::SuccessorGenerator&,
                                                  const tioa::StartSet&, const ExploreOptions&,
                                                  const ExploreHooks&, const ZeroTimeReduction*);

} // namespace checker
