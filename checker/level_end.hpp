#pragma once
// The end of a level (one thread): the workers' counts, stuck states and edges enter the
// run, the new states get their breadth-first ids and parents (discovery.hpp), and the
// first target found, if any, ends the run there. After it, ids, parents, counts, edges
// and the target are those of a sequential breadth-first search, whatever the number of
// workers:
// - with one worker the states were inserted in key order already, and it wrote their
//   parents; with several, the level is renumbered in key order and the parents are
//   taken from the keys;
// - edges go in as a sequential search records them: first those to states stored before
//   the level, then those to the level's new states, each in frontier order;
// - the run stops at the target with the smallest id; the states after it are forgotten,
//   as a sequential search would not have inserted them.
// The counts go in whole, whatever stops the level: they are then the same for every
// thread count. A level that a limit (time, memory, a stop from outside) cut short, with
// no target in it, keeps its states in the order the workers inserted them, with its
// holes filled, and gathers no edges: it stops within the limit, and which states got
// in was a race anyway.

#include <optional>
#include <span>

#include "checker/discovery.hpp"
#include "checker/expansion.hpp"
#include "checker/exploration.hpp"
#include "checker/memory_budget.hpp"

namespace checker {

// What renumbering a level of `count` states (holes included) adds at least to what the
// explorer holds, when its states move in place: the discovery's buffers for the order
// and the new ids beyond what they hold already, the store's slots and the store's bit
// per state. The explorer counts it as held while a
// level with several workers grows, so that the level's end fits in the memory limit.
std::size_t renumbering_bytes(const Discovery& discovery, std::uint64_t count);

// Why the run stops after this level, if it does: a target found, the state limit, or
// the memory limit (met while the store grew or the level was numbered).
std::optional<StopReason> finish_level(std::span<const Worker> workers, const Level& level,
                                       Exploration& ex, bool record_edges, MemoryBudget& budget);

} // namespace checker
