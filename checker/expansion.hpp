#pragma once
// Expansion: the workers of a level take chunks of the frontier (ranges of ids, in order)
// until none is left, and insert the successors into the store themselves, concurrently
// (state_store.hpp); the store grows while they wait at the growth gate
// (growth_gate.hpp). Each new state keeps the step that found it first (discovery.hpp), so
// that level_end.hpp can number the level as a sequential search would. On the
// fingerprint store the frontier's states and the new ones are in level_states.hpp, and the
// store is asked about fingerprints (insertion.hpp's store_key()). On the compressed store
// the frontier's states are decoded from the tree, with their nodes' ids, and the store is
// asked about each successor's key in it (state_tree.hpp), made from its parent's parts as
// it is generated (or at its insertion, when a table of parts was out of room).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "checker/discovery.hpp"
#include "checker/exploration.hpp"
#include "checker/growth_gate.hpp"
#include "checker/hooks.hpp"
#include "checker/insertion.hpp"
#include "checker/interrupt.hpp"
#include "checker/level_states.hpp"
#include "checker/memory_budget.hpp"
#include "checker/progress.hpp"
#include "checker/run_limits.hpp"
#include "checker/state_buffer.hpp"
#include "checker/zero_time_reduction.hpp"
#include "tioa/successors.hpp"

namespace checker {

// Ids a worker of a concurrent level takes at a time.
inline constexpr std::uint32_t id_block_size = 256;

// What the workers of one level share (the signals, the gate, the discovery keys and the
// store are written concurrently).
struct Level {
  const tioa::SuccessorGenerator& generator;
  StateStore& store;
  Discovery& discovery;          // with several workers
  MappedVector<StateId>& parent; // written by a worker alone (room made at the gate)
  GrowthGate& gate;
  StateId begin, end;       // the frontier: ids begin.. end - 1
  std::uint64_t max_states; // 0: no limit
  std::uint32_t depth;
  std::size_t workers;  // expanding this level
  const Limits& limits; // the time limit (the others are checked elsewhere)
  Progress& progress;   // drawn by the first worker only
  LevelSignals& signals;
  const ZeroTimeReduction* reduction; // null: every successor
  LevelStates* states;              // the fingerprint store's two levels (nullptr: the exact store)
  bool stop_at_state_limit = false; // ExploreOptions::stop_at_state_limit
  StateTree* tree = nullptr;        // the compressed store's parts (nullptr: another store)

  bool concurrent() const { return workers > 1; }
  // The ids a worker takes at a time (see StateStore::IdBlock): one when it is alone, so
  // that its ids are in breadth-first order already.
  std::uint32_t id_block() const { return concurrent() ? id_block_size : 1; }
  // The first id of the level being built.
  StateId first_new() const { return discovery.first(); }
  // A state of the frontier (on the fingerprint store unpacked into `scratch`, words()).
  // The compressed store's are decoded by Worker::expand, with their nodes' ids.
  const Word* frontier(StateId id, Word* scratch) const {
    return states ? states->frontier(id, scratch) : store.state(id);
  }
};

// Frontiers smaller than this are expanded by one worker.
inline constexpr std::size_t parallel_threshold = 4096;

// The workers that expand a level of `frontier_size` states, out of `available`.
inline std::size_t workers_for(std::size_t frontier_size, std::size_t available) {
  return frontier_size < parallel_threshold ? 1 : available;
}

// What one thread produces while expanding its chunks of the frontier; its buffers keep
// their memory from level to level.
class Worker {
public:
  explicit Worker(std::uint32_t words)
      : pending_states(words), scratch(words + 1, 0), representative(words + 1, 0),
        unpacked(words, 0) {}

  std::size_t writer = 0; // this worker's index: its arena of the fingerprint store's level

  // The level's results, in frontier order (its chunks are taken in order).
  std::vector<Edge> known_edges; // to states stored before the level (with record_edges)
  std::vector<Edge> new_edges;   // to states of the level being built (with record_edges)
  std::vector<StateId> stuck;    // expanded states with no successor
  std::vector<StateId> targets;  // new states that are targets
  std::uint64_t edge_count = 0;
  std::uint64_t expanded = 0;
  std::uint64_t inserted = 0; // new states this worker inserted in the level
  StateStore::IdBlock ids;    // the unused end is a hole in the level's ids
  std::exception_ptr error;
  Allowance allowance;
  ZeroTimeReduction::Scratch reduction; // with a reduction

  // What this worker holds.
  std::size_t bytes() const {
    return pending_states.bytes() + pending.capacity() * sizeof(Pending) +
           (known_edges.capacity() + new_edges.capacity()) * sizeof(Edge) +
           (stuck.capacity() + targets.capacity()) * sizeof(StateId);
  }

  // Forgets the last level's results, keeping the memory.
  void clear();

  // Expands frontier ids [begin, end) of the level; stops early when a limit is met (and
  // signals it), or on an exception, which it keeps in `error`: then it returns false,
  // and the level stops. The worker on the calling thread draws the progress line.
  template <class Hooks>
  bool expand(const Hooks& hooks, const Level& level, StateId begin, StateId end,
              bool calling_thread);

  // Room in the level buffers for the `successors` of one state (as edges when
  // `edges_too`, a stuck state when there are none), growing them only within the
  // allowance; false, with nothing grown past it, when it would be exceeded.
  bool make_room(std::size_t successors, bool edges_too) {
    const std::size_t edge_room = edges_too ? successors : 0;
    const std::size_t stuck_room = successors == 0 ? 1 : 0;
    if (known_edges.capacity() - known_edges.size() >= edge_room &&
        new_edges.capacity() - new_edges.size() >= edge_room &&
        stuck.capacity() - stuck.size() >= stuck_room)
      return true;
    return grow_room(edge_room, stuck_room);
  }

  // Room in this worker's arena of the fingerprint store's level for `states` more states,
  // within the allowance, which also counts the discovery keys of the states it inserts
  // (they grow with the level, not at the growth gate).
  bool make_state_room(const Level& level, std::size_t states) {
    if (!level.states)
      return true;
    const std::size_t growth =
        level.states->growth_bytes(writer, states) + states * Discovery::bytes_per_state;
    if (!allowance.fits(own_bytes(level.states), growth))
      return false;
    level.states->make_room(writer, states);
    return true;
  }
  // What this worker holds and adds in this level: bytes(), and on the fingerprint store
  // (`states`) its arena of the level being built and the discovery keys of its states.
  std::size_t own_bytes(const LevelStates* states) const {
    return bytes() +
           (states ? states->writer_bytes(writer) + inserted * Discovery::bytes_per_state : 0);
  }

private:
  struct Pending {
    std::uint64_t hash;        // of the key the store holds
    std::uint64_t fingerprint; // (fingerprint store) the key; (compressed store) when keyed
    std::uint32_t duration;
    bool keyed = false; // (compressed store) the key is made (else: at the insertion)
  };
  // A state of the batch being expanded: its successors are pending[first..first+count).
  struct Expanded {
    StateId id;
    std::uint32_t first, count;
  };
  // A batch ends after this many states, or once it has this many successors.
  static constexpr std::uint32_t batch_states = 16;
  static constexpr std::size_t batch_successors = 64;

  bool grow_room(std::size_t edge_room, std::size_t stuck_room);
  template <class T> bool grow_within(std::vector<T>& v, std::size_t more);
  // The checks made every 1024 states (progress, interrupt, time and memory limits);
  // false when the level stops.
  bool keep_going(const Level& level, StateId id, bool calling_thread);
  // Appends the successors of `state` to the pending ones, prefetching their slots.
  template <class Hooks>
  void generate(const Hooks& hooks, const Level& level, const Word* state, std::uint32_t words);
  // Inserts or finds successor `step` of `from` (pending[index]); false when the level stops.
  template <class Hooks>
  bool insert(const Hooks& hooks, const Level& level, StateId from, std::uint32_t step,
              std::uint32_t index);

  StateBuffer pending_states; // successors of the batch being expanded
  std::vector<Pending> pending;
  std::vector<Expanded> batch;
  std::uint64_t checks = 0;         // made by keep_going()
  std::vector<Word> scratch;        // the successor generator's
  std::vector<Word> representative; // a successor's (the canonical hook)
  std::vector<Word> unpacked;       // a frontier state (the fingerprint and compressed stores)
  // The compressed store's: the ids of the nodes of the frontier state being expanded
  // (StateTree::decode()) and of a successor's.
  std::vector<std::uint32_t> frontier_ids, tree_ids;
};

template <class Hooks>
bool Worker::insert(const Hooks& hooks, const Level& level, StateId from, std::uint32_t step,
                    std::uint32_t index) {
  const Word* succ = pending_states[index];
  const Pending& p = pending[index];
  const Word* key_words = level.states || p.keyed ? &p.fingerprint : succ;
  std::uint64_t hash = p.hash;
  bool keyed = !level.tree || p.keyed;
  Word tree_key = 0; // the compressed store's key of succ, made here
  const std::uint64_t key = Discovery::key(from, step);
  StateId to = 0;
  bool fresh = false;
  for (;;) {
    if (!level.gate.checkpoint())
      return false;
    if (!keyed) {
      tree_ids.resize(level.tree->scratch_size());
      const std::optional<Word> made = level.tree->insert(succ, tree_ids.data());
      if (!made) { // a table of parts is out of room
        level.gate.request();
        continue;
      }
      tree_key = *made;
      key_words = &tree_key;
      hash = hash_state(&tree_key, 1);
      keyed = true;
    }
    if (level.max_states && level.store.size() >= level.max_states) {
      // At the state limit only stored states are found; a new one ends the run, and the
      // level goes on for the counts (unless the run stops at once: Level::stop_at_state_limit).
      const auto known = level.store.find(key_words, hash);
      if (!known) {
        level.signals.state_limit = true;
        if (!level.stop_at_state_limit)
          return true;
        level.gate.stop();
        return false;
      }
      to = *known;
      break;
    }
    const StateStore::Claim claim =
        level.store.find_or_insert(key_words, hash, ids, [&](StateId id, std::uint32_t slot) {
          if (level.states)
            level.states->put(id, succ, writer);
          if (id + ids.size == ids.end) // a new block: its other ids are holes until taken
            level.discovery.holes(id + 1, ids.end);
          if (level.concurrent()) {
            level.discovery.found(id, key);
            level.discovery.placed(id, slot);
          } else { // alone, in key order: the parent is known now
            level.parent.push_back(from);
          }
        });
    if (claim.kind == StateStore::Claim::Kind::full) {
      level.gate.request();
      continue;
    }
    to = claim.id;
    fresh = claim.kind == StateStore::Claim::Kind::fresh;
    break;
  }
  if (fresh) {
    ++inserted;
    if (is_target(hooks, succ))
      targets.push_back(to);
  } else if (to >= level.first_new() && level.concurrent()) {
    level.discovery.found_again(to, key, level.concurrent());
  }
  if (records_edges(hooks))
    (to < level.first_new() ? known_edges : new_edges).push_back({from, edge_to(to, p.duration)});
  return true;
}

template <class Hooks>
bool Worker::expand(const Hooks& hooks, const Level& level, StateId begin, StateId end,
                    bool calling_thread) {
  const std::uint32_t words = level.generator.words();
  const bool record_edges = records_edges(hooks);
  try {
    StateId next_check = begin + 1024;
    for (StateId id = begin; id < end;) {
      if (id >= next_check) {
        next_check = id + 1024;
        if (!keep_going(level, id, calling_thread))
          return false;
      }
      // A batch of states (ids in order): every successor is generated first and its slot
      // in the store prefetched; then, the slots having arrived, the states they hold are
      // prefetched; only then is each successor looked up, in the same order as one at a
      // time, so the lookups overlap their cache misses instead of waiting for each.
      pending_states.clear();
      pending.clear();
      batch.clear();
      const StateId batch_end = std::min<StateId>(end, id + batch_states);
      for (; id < batch_end && pending.size() < batch_successors; ++id) {
        const Word* state = unpacked.data();
        if (level.tree) { // with its nodes' ids, for its successors' keys
          frontier_ids.resize(level.tree->scratch_size());
          level.tree->decode(level.store.state(id)[0], unpacked.data(), frontier_ids.data());
        } else {
          state = level.frontier(id, unpacked.data());
        }
        if (!expands(hooks, state))
          continue;
        const std::size_t first = pending.size();
        generate(hooks, level, state, words);
        batch.push_back({id, static_cast<std::uint32_t>(first),
                         static_cast<std::uint32_t>(pending.size() - first)});
      }
      for (const Pending& p : pending)
        if (!level.tree || p.keyed)
          level.store.prefetch_state(p.hash);
      for (const Expanded& e : batch) {
        // Edges pile up in the level buffers, which grow only within this worker's share
        // of the memory left.
        if (!make_room(e.count, record_edges) || !make_state_room(level, e.count)) {
          level.signals.out_of_memory = true;
          return false;
        }
        ++expanded;
        edge_count += e.count;
        if (e.count == 0)
          stuck.push_back(e.id);
        for (std::uint32_t k = 0; k < e.count; ++k)
          if (!insert(hooks, level, e.id, k, e.first + k))
            return false;
      }
    }
  } catch (...) {
    error = std::current_exception();
    return false;
  }
  return true;
}

template <class Hooks>
void Worker::generate(const Hooks& hooks, const Level& level, const Word* state,
                      std::uint32_t words) {
  auto take = [&](const Word* succ, std::uint32_t duration) {
    if (canonicalises(hooks)) {
      std::copy(succ, succ + words, representative.begin());
      canonicalise(hooks, representative.data());
      succ = representative.data();
    }
    pending_states.push(succ);
    if (level.tree) {
      // The key, from the parts of `state` it shares; made at the insertion instead when a
      // table of parts is out of room (the workers wait for its growth there).
      tree_ids.resize(level.tree->scratch_size());
      const std::optional<Word> made =
          level.tree->insert_near(succ, state, frontier_ids.data(), tree_ids.data());
      if (!made) {
        pending.push_back({0, 0, duration, false});
        return;
      }
      const std::uint64_t hash = hash_state(&*made, 1);
      level.store.prefetch(hash);
      pending.push_back({hash, *made, duration, true});
      return;
    }
    std::uint64_t fingerprint_of = 0;
    const StoreKey key = store_key(succ, words, level.states != nullptr, fingerprint_of);
    level.store.prefetch(key.hash);
    pending.push_back({key.hash, fingerprint_of, duration});
  };
  const std::optional<std::size_t> reduced =
      level.reduction ? level.reduction->reduce(state, reduction) : std::nullopt;
  if (reduced) {
    for (std::size_t k = 0; k < *reduced; ++k)
      take(reduction.successors.data() + k * words, reduction.durations[k]);
    return;
  }
  level.generator.successors(state, scratch.data(),
                             [&](const Word* succ, const tioa::StepLabel& label) {
                               take(succ, level.generator.duration(label));
                             });
}

inline bool Worker::keep_going(const Level& level, StateId id, bool calling_thread) {
  if (calling_thread) // (chunks are taken in order: roughly what is left)
    level.progress.update(level.store.size(), level.end - id, level.depth);
  if (interrupted()) // stop_after_level() names the reason
    return false;
  if (level.limits.max_seconds > 0 || level.limits.deadline) {
    if (level.signals.out_of_time.load(std::memory_order_relaxed))
      return false;
    if (level.limits.out_of_time(level.progress.elapsed())) {
      level.signals.out_of_time = true;
      return false;
    }
  }
  if (level.signals.out_of_memory.load(std::memory_order_relaxed) || level.gate.stopped())
    return false;
  // What the budget does not see (the model's memos, the allocator's slack) shows in the
  // resident memory.
  if (++checks % 16 == 0 && resident_over_limit(level.limits)) {
    level.signals.out_of_memory = true;
    return false;
  }
  return true;
}

// Expands a whole level with `workers` (as many as level.workers): each takes the next
// chunk of the frontier (in order) until none is left, the first worker on the calling
// thread, so that a worker whose states are cheap is not left waiting for the others.
// Each worker's results are in frontier order, and finish_level merges them in that
// order. Each worker may grow its buffers by an equal share of the memory left; the run's
// peak counts what they reached. The first error of a worker, in worker order, is
// rethrown.
template <class Hooks>
void expand_level(std::span<Worker> workers, const Hooks& hooks, const Level& level,
                  MemoryBudget& budget) {
  const std::size_t used = workers.size();
  for (Worker& w : workers) {
    w.clear();
    w.ids = {0, 0, level.id_block()};
  }
  const std::size_t held = budget.held();
  const std::size_t share = budget.share_left(held, used);
  for (Worker& w : workers)
    w.allowance.begin_level(w.own_bytes(level.states), share);
  const std::uint64_t n = level.end - level.begin;
  const std::uint64_t chunk =
      used == 1 ? n : std::clamp<std::uint64_t>(n / (used * 64), 256, 16384);
  std::atomic<std::uint64_t> next{0};
  auto run = [&](Worker& w, bool calling_thread) {
    for (;;) {
      const std::uint64_t at = next.fetch_add(chunk, std::memory_order_relaxed);
      if (at >= n)
        break;
      const auto begin = static_cast<StateId>(level.begin + at);
      const auto end = static_cast<StateId>(level.begin + std::min(n, at + chunk));
      if (!w.expand(hooks, level, begin, end, calling_thread)) {
        next.store(n, std::memory_order_relaxed); // the level stops: nobody takes more
        break;
      }
    }
    level.gate.leave();
  };
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < used; ++t)
    threads.emplace_back([&, t] { run(workers[t], false); });
  run(workers[0], true);
  for (auto& thread : threads)
    thread.join();
  std::size_t level_peak = held;
  for (const Worker& w : workers) {
    if (w.error)
      std::rethrow_exception(w.error);
    level_peak += w.allowance.level_growth();
  }
  if (level.gate.error())
    std::rethrow_exception(level.gate.error());
  budget.note(level_peak);
}

} // namespace checker
