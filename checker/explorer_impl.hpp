#pragma once
// explore() (explorer.hpp) as the pipeline of its parts:
//   start insertion -> per level: expansion (parallel, inserting) -> level end -> limits.
// Included by explorer.hpp; explorer.cpp compiles it once for NoHooks and ExploreHooks.
// On the fingerprint store (fingerprint.hpp) the same pipeline runs with fingerprints as
// the store's keys and the full states of two levels in level_states.hpp.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "checker/collective.hpp"
#include "checker/discovery.hpp"
#include "checker/expansion.hpp"
#include "checker/explorer.hpp"
#include "checker/growth_gate.hpp"
#include "checker/insertion.hpp"
#include "checker/level_end.hpp"
#include "checker/level_states.hpp"
#include "checker/memory_budget.hpp"
#include "checker/progress.hpp"
#include "checker/run_limits.hpp"
#include "checker/start_insertion.hpp"

namespace checker {

template <class Hooks>
Exploration explore(const tioa::SuccessorGenerator& generator, const tioa::StartSet& start,
                    const ExploreOptions& options, const Hooks& hooks,
                    const ZeroTimeReduction* reduction) {
  // Every check explores through here, except those that run distributed
  // (distributed_explorer.hpp): under mpirun the others say so rather than run once per rank.
  if (distributed())
    throw NotDistributed("this property does not run distributed yet (invariants, deadlock / "
                         "time-lock checks and the legal-set closure do): run it without "
                         "mpirun");
  const Limits& limits = options.limits;
  const bool fingerprints = options.store == StoreKind::fingerprint;
  // Representatives and edges are read as states after the run: the fingerprint store has
  // none to read.
  if (fingerprints && (canonicalises(hooks) || records_edges(hooks)))
    throw std::invalid_argument("the fingerprint store keeps no states to canonicalise or "
                                "edges to record: use the exact store");
  Exploration ex(generator.words(), options.store);
  // What the property's budget has left (options.hpp): nothing left, nothing explored.
  const std::uint64_t max_states = limits.states_left();
  if (limits.states_exhausted()) {
    ex.stop = StopReason::state_limit;
    ex.threads = 1;
    return ex;
  }
  if (fingerprints)
    ex.start = start;
  LevelStates level_states(generator.words());
  LevelStates* const states = fingerprints ? &level_states : nullptr;
  ex.threads = options.threads == 0 ? 1 : options.threads;
  ex.store.set_inserters(ex.threads, id_block_size);
  if (ex.tree)
    ex.tree->set_inserters(ex.threads);
  Progress progress(options.progress, options.task.empty() ? "exploring" : options.task);
  std::vector<Worker> workers(ex.threads, Worker(generator.words()));
  for (std::size_t w = 0; w < workers.size(); ++w)
    workers[w].writer = w;
  level_states.set_writers(workers.size());
  Discovery discovery;
  // The memory limit counts the store, the parents, the edges, the discovery keys of the
  // level being built and its buffers for the level's end, the workers' buffers, (fingerprint
  // store) the two levels' states, and, while several workers build a level, what its renumbering
  // will need at least (level_end.hpp).
  bool concurrent = false;        // the level being expanded has several workers
  std::size_t active_workers = 1; // expanding it
  StateId level_end = 0;          // the end of its frontier
  MemoryBudget budget(memory_left(limits), [&] {
    std::size_t bytes =
        ex.memory_bytes() + discovery.bytes(ex.store.size()) + (states ? states->bytes() : 0);
    if (concurrent)
      bytes += renumbering_bytes(discovery, ex.store.size() - level_end);
    for (const Worker& w : workers)
      bytes += w.bytes();
    return bytes;
  });
  Insertion insertion(ex, budget, max_states, states);
  // Room for the states of the level being built, up to the store's id limit (fingerprint
  // store).
  auto reserve_states = [&] {
    if (!states)
      return true;
    if (!budget.fits(states->reserve_bytes(ex.store.id_limit())))
      return false;
    states->reserve(ex.store.id_limit());
    return true;
  };

  std::optional<StopReason> stop =
      insert_start_states(start, ex, hooks, insertion, [&](bool stopped) {
        std::optional<StopReason> reason;
        if (!stopped)
          reason = time_or_memory_exceeded(limits, progress, budget);
        progress.update(ex.store.size(), ex.store.size(), 0);
        return reason;
      });

  // The store grows by an eighth at a time (and the discovery keys with it), while the
  // workers wait at the gate; so do the compressed store's tables of parts, when they ask.
  // A worker alone writes the parents as it inserts: room for as many as the store.
  auto parents_room = [&] { return ex.store.id_limit() - ex.parent.size(); };
  auto reshare = [&] {
    // What the store took is no longer left for the workers' own buffers: each gets an
    // equal share of what is left now.
    const std::size_t share = budget.share_left(budget.held(), active_workers);
    for (std::size_t w = 0; w < active_workers; ++w)
      workers[w].allowance.reshare(workers[w].own_bytes(states), share);
  };
  auto grow_store = [&] {
    if (ex.tree && ex.tree->needs_room()) {
      if (!budget.fits(ex.tree->room_bytes()))
        return false;
      ex.tree->make_room();
      if (ex.store.size() < ex.store.room()) { // the keys' table has room
        reshare();
        return true;
      }
    }
    const std::uint64_t more = std::max<std::uint64_t>(ex.store.size() / 8, 4096);
    if (!budget.fits(ex.store.room_bytes(more) +
                     ex.parent.growth_bytes(parents_room() + more + id_block_size)))
      return false;
    const std::uint64_t tables = ex.store.tables_built();
    // The ids of the level's blocks that no state took yet are holes (discovery.hpp); the
    // level's states move in a new table, and the discovery keeps their new slots.
    std::function<bool(StateId)> holds;
    std::function<void(StateId, std::uint32_t)> placed;
    if (concurrent) {
      holds = [&](StateId id) {
        return id < discovery.first() || discovery.key_of(id) != Discovery::hole;
      };
      placed = [&](StateId id, std::uint32_t slot) {
        if (id >= discovery.first())
          discovery.placed(id, slot);
      };
    }
    ex.store.make_room(more, holds, placed);
    if (!concurrent && ex.store.tables_built() != tables) // (no slots were kept)
      discovery.forget_slots();
    discovery.make_room(ex.store.id_limit());
    ex.parent.grow(parents_room());
    if (!reserve_states())
      return false;
    reshare();
    return true;
  };
  LevelSignals signals;
  StateId begin = 0, end = static_cast<StateId>(ex.store.size());
  if (states)
    states->next_level(end);
  while (begin < end && !stop) {
    const StateId first = end;
    level_end = end;
    std::optional<StopReason> level_stop;
    for (std::size_t used = workers_for(end - begin, workers.size());;) {
      concurrent = used > 1;
      active_workers = used;
      discovery.begin(first);
      discovery.make_room(ex.store.id_limit());
      if (!budget.grow_within(ex.parent, parents_room()) || !reserve_states()) {
        level_stop = StopReason::memory_limit;
        break;
      }
      GrowthGate gate(used, grow_store);
      const Level level{generator,    ex.store,  discovery, ex.parent,
                        gate,         begin,     end,       max_states,
                        ex.depth,     used,      limits,    progress,
                        signals,      reduction, states,    options.stop_at_state_limit,
                        ex.tree.get()};
      const std::span<Worker> active(workers.data(), used);
      expand_level(active, hooks, level, budget);
      if (signals.state_limit && used > 1 && !signals.out_of_time && !signals.out_of_memory &&
          !options.stop_at_state_limit) {
        // Which states fit under the limit depends on the race between the workers: the
        // level is done again by one worker, which inserts them in breadth-first order.
        ex.store.truncate(first);
        signals.state_limit = false;
        used = 1;
        continue;
      }
      concurrent = false; // (finish_level asks for the renumbering's memory itself)
      level_stop = finish_level(active, level, ex, records_edges(hooks), budget);
      break;
    }
    stop = stop_after_level(level_stop, signals, limits, progress, budget);
    budget.note(budget.held());
    begin = end;
    end = static_cast<StateId>(ex.store.size());
    if (states)
      states->next_level(end - begin);
    ++ex.depth;
    progress.update(ex.store.size(), end - begin, ex.depth);
  }
  if (stop)
    ex.stop = *stop;
  ex.reduction = reduction != nullptr;
  for (const Worker& w : workers)
    ex.reduced_states += w.reduction.reduced;
  ex.peak_memory_bytes = budget.peak();
  ex.seconds = progress.elapsed();
  limits.spend_states(ex.store.size());
  return ex;
}

} // namespace checker
