#pragma once
// Expansion: a worker turns a contiguous chunk of the frontier into candidates (successors
// that were not in the store when the level began) and edges to states that were. The
// store is only read here, so the workers of a level run in parallel, each on its own
// chunk and its own buffers; merge.hpp then inserts the candidates in frontier order.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <span>
#include <thread>
#include <vector>

#include "checker/exploration.hpp"
#include "checker/hooks.hpp"
#include "checker/memory_budget.hpp"
#include "checker/progress.hpp"
#include "checker/run_limits.hpp"
#include "checker/state_buffer.hpp"
#include "tioa/successors.hpp"

namespace checker {

// A successor not in the store when its level began; its state is kept alongside.
struct Candidate {
  std::uint64_t hash;
  StateId from;
  std::uint8_t duration;
  bool target;
};

// What the workers of one level read (the signals they also write).
struct Level {
  const tioa::SuccessorGenerator& generator;
  const StateStore& store;
  std::span<const StateId> frontier;
  std::uint32_t depth;
  std::size_t workers; // expanding this level
  double max_seconds;  // 0: no time limit
  Progress& progress;  // drawn by the first worker only
  LevelSignals& signals;
};

// Frontiers smaller than this are expanded by one worker.
inline constexpr std::size_t parallel_threshold = 4096;

// The workers that expand a level of `frontier_size` states, out of `available`.
inline std::size_t workers_for(std::size_t frontier_size, std::size_t available) {
  return frontier_size < parallel_threshold ? 1 : available;
}

// What one thread produces while expanding its chunk of the frontier; its buffers keep
// their memory from level to level.
class Worker {
public:
  explicit Worker(std::uint32_t words)
      : states(words), pending_states(words), scratch(words + 1, 0), representative(words + 1, 0) {}

  // The level's results, in the order of the chunk.
  StateBuffer states;                // the candidates' states
  std::vector<Candidate> candidates; // successors not in the store
  std::vector<Edge> edges;           // to states in the store (with record_edges)
  std::vector<StateId> stuck;        // expanded states with no successor
  std::uint64_t edge_count = 0;
  std::uint64_t expanded = 0;
  std::exception_ptr error;
  Allowance allowance;

  // What this worker holds.
  std::size_t bytes() const {
    return pending_states.bytes() + states.bytes() + pending.capacity() * sizeof(Pending) +
           candidates.capacity() * sizeof(Candidate) + edges.capacity() * sizeof(Edge) +
           stuck.capacity() * sizeof(StateId);
  }

  // Forgets the last level's results, keeping the memory.
  void clear();

  // Expands frontier[begin, end) of the level; stops early when a limit is met (and
  // signals it), or on an exception, which it keeps in `error`. The worker on the calling
  // thread draws the progress line.
  template <class Hooks>
  void expand(const Hooks& hooks, const Level& level, std::size_t begin, std::size_t end,
              bool calling_thread);

  // Room in the level buffers for the `successors` of one state (as candidates, or as
  // edges to known states when `edges_too`), growing them only within the allowance;
  // false, with nothing grown past it, when it would be exceeded.
  bool make_room(std::size_t successors, bool edges_too) {
    const std::size_t edge_room = edges_too ? successors : 0;
    const std::size_t stuck_room = successors == 0 ? 1 : 0;
    if (states.growth_bytes(successors) == 0 &&
        candidates.capacity() - candidates.size() >= successors &&
        edges.capacity() - edges.size() >= edge_room &&
        stuck.capacity() - stuck.size() >= stuck_room)
      return true;
    return grow_room(successors, edge_room, stuck_room);
  }

private:
  struct Pending {
    std::uint64_t hash;
    std::uint32_t duration;
  };
  bool grow_room(std::size_t successors, std::size_t edge_room, std::size_t stuck_room);
  template <class T> bool grow_within(std::vector<T>& v, std::size_t more);

  StateBuffer pending_states; // successors of the state being expanded
  std::vector<Pending> pending;
  std::vector<Word> scratch;        // the successor generator's
  std::vector<Word> representative; // a successor's (the canonical hook)
};

template <class Hooks>
void Worker::expand(const Hooks& hooks, const Level& level, std::size_t begin, std::size_t end,
                    bool calling_thread) {
  const std::uint32_t words = level.store.words();
  const bool record_edges = records_edges(hooks);
  try {
    for (std::size_t i = begin; i < end; ++i) {
      if (((i - begin) & 1023) == 1023) {
        if (calling_thread)
          level.progress.update(level.store.size(),
                                level.frontier.size() - (i - begin) * level.workers, level.depth);
        if (level.max_seconds > 0) {
          if (level.signals.out_of_time.load(std::memory_order_relaxed))
            return;
          if (level.progress.elapsed() > level.max_seconds) {
            level.signals.out_of_time = true;
            return;
          }
        }
        if (level.signals.out_of_memory.load(std::memory_order_relaxed))
          return;
      }
      const StateId id = level.frontier[i];
      const Word* state = level.store.state(id);
      if (!expands(hooks, state))
        continue;
      // Generate every successor first and prefetch its slot in the store, so that the
      // lookups below overlap their cache misses instead of waiting for each in turn.
      pending_states.clear();
      pending.clear();
      const std::size_t n = level.generator.successors(
          state, scratch.data(), [&](const Word* succ, const tioa::StepLabel& label) {
            if (canonicalises(hooks)) {
              std::copy(succ, succ + words, representative.begin());
              canonicalise(hooks, representative.data());
              succ = representative.data();
            }
            const std::uint64_t h = hash_state(succ, words);
            level.store.prefetch(h);
            pending_states.push(succ);
            pending.push_back({h, level.generator.duration(label)});
          });
      // The successors pile up in the level buffers, which grow only within this
      // worker's share of the memory left.
      if (!make_room(n, record_edges)) {
        level.signals.out_of_memory = true;
        return;
      }
      ++expanded;
      for (std::size_t k = 0; k < n; ++k) {
        const Word* succ = pending_states[k];
        const Pending& p = pending[k];
        if (const auto known = level.store.find(succ, p.hash)) {
          if (record_edges)
            edges.push_back({id, edge_to(*known, p.duration)});
          continue;
        }
        states.push(succ);
        candidates.push_back(
            {p.hash, id, static_cast<std::uint8_t>(p.duration), is_target(hooks, succ)});
      }
      edge_count += n;
      if (n == 0)
        stuck.push_back(id);
    }
  } catch (...) {
    error = std::current_exception();
  }
}

// Expands a whole level with `workers` (as many as level.workers): the frontier is cut into
// one contiguous chunk per worker, the first expanded on the calling thread. Each worker
// may grow by an equal share of the memory left; the run's peak counts what they reached.
// The first error of a worker, in worker order, is rethrown.
template <class Hooks>
void expand_level(std::span<Worker> workers, const Hooks& hooks, const Level& level,
                  MemoryBudget& budget) {
  const std::size_t used = workers.size();
  for (Worker& w : workers)
    w.clear();
  // The store and the frontiers do not change while the level is expanded.
  const std::size_t held = budget.held();
  const std::size_t share = budget.share_left(held, used);
  for (Worker& w : workers)
    w.allowance.begin_level(w.bytes(), share);
  const std::size_t n = level.frontier.size();
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < used; ++t)
    threads.emplace_back(
        [&, t] { workers[t].expand(hooks, level, n * t / used, n * (t + 1) / used, false); });
  workers[0].expand(hooks, level, 0, n / used, true);
  for (auto& thread : threads)
    thread.join();
  std::size_t level_peak = held;
  for (const Worker& w : workers) {
    if (w.error)
      std::rethrow_exception(w.error);
    level_peak += w.allowance.level_growth();
  }
  budget.note(level_peak);
}

} // namespace checker
