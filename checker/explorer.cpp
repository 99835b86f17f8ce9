#include "checker/explorer.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <limits>
#include <thread>

#include "checker/progress.hpp"

namespace checker {

const char* describe(StopReason reason) {
  switch (reason) {
  case StopReason::finished:
    return "finished";
  case StopReason::found:
    return "found";
  case StopReason::state_limit:
    return "state limit reached";
  case StopReason::time_limit:
    return "time limit reached";
  default:
    return "memory limit reached";
  }
}

namespace {

// Bytes of the bigger buffer that making room for `more` elements in `v` allocates, 0 when
// there is room; grow() then allocates exactly that. A buffer at least doubles.
template <class T> std::size_t growth_bytes(const std::vector<T>& v, std::size_t more) {
  if (v.capacity() - v.size() >= more)
    return 0;
  return std::max({2 * v.capacity(), v.size() + more, std::size_t{64}}) * sizeof(T);
}
template <class T> void grow(std::vector<T>& v, std::size_t more) {
  if (v.capacity() - v.size() < more)
    v.reserve(std::max({2 * v.capacity(), v.size() + more, std::size_t{64}}));
}

struct Candidate {
  std::uint64_t hash;
  StateId from;
  std::uint8_t duration;
  bool target;
};

// What one thread produces while expanding its chunk of the frontier; reused each level.
// A growable run of packed states that never shrinks: clear() keeps the memory, and
// appending copies words without initialising them first.
class StateBuffer {
public:
  explicit StateBuffer(std::uint32_t words) : words_(words) {}
  void clear() { size_ = 0; }
  void push(const Word* state) {
    if (size_ + words_ > storage_.size())
      storage_.resize(grown(size_ + words_));
    for (std::uint32_t i = 0; i < words_; ++i)
      storage_[size_ + i] = state[i];
    size_ += words_;
  }
  const Word* operator[](std::size_t index) const { return storage_.data() + index * words_; }
  std::size_t bytes() const { return storage_.capacity() * sizeof(Word); }
  // As growth_bytes() and grow() for vectors, counted in states.
  std::size_t growth_bytes(std::size_t more) const {
    const std::size_t needed = size_ + more * words_;
    return needed <= storage_.size() ? 0 : grown(needed) * sizeof(Word);
  }
  void grow(std::size_t more) {
    const std::size_t needed = size_ + more * words_;
    if (needed > storage_.size())
      storage_.resize(grown(needed));
  }

private:
  // Resizing to this allocates exactly this many words (the buffer at least doubles).
  std::size_t grown(std::size_t needed) const {
    return std::max({2 * storage_.size(), needed, std::size_t{64} * words_});
  }

  std::uint32_t words_;
  std::size_t size_ = 0;
  std::vector<Word> storage_;
};

struct Pending {
  std::uint64_t hash;
  std::uint32_t duration;
};

struct Worker {
  explicit Worker(std::uint32_t words) : pending_states(words), states(words) {}
  StateBuffer pending_states; // successors of the state being expanded
  std::vector<Pending> pending;
  StateBuffer states;
  std::vector<Candidate> candidates;
  std::vector<Edge> edges;
  std::vector<StateId> stuck;
  std::vector<Word> scratch;
  std::vector<Word> canonical; // a successor's representative (ExploreHooks::canonical)
  std::uint64_t edge_count = 0;
  std::uint64_t expanded = 0;
  std::exception_ptr error;
  // The bytes this worker may hold in the level in progress, and the most it held.
  std::size_t allowance = std::numeric_limits<std::size_t>::max();
  std::size_t level_start_bytes = 0, peak_bytes = 0;

  // What this worker holds (its buffers keep their memory between levels).
  std::size_t bytes() const {
    return pending_states.bytes() + states.bytes() + pending.capacity() * sizeof(Pending) +
           candidates.capacity() * sizeof(Candidate) + edges.capacity() * sizeof(Edge) +
           stuck.capacity() * sizeof(StateId);
  }

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
    if (!fits(states.growth_bytes(successors)))
      return false;
    states.grow(successors);
    return grow_within(candidates, successors) && grow_within(edges, edge_room) &&
           grow_within(stuck, stuck_room);
  }
  template <class T> bool grow_within(std::vector<T>& v, std::size_t more) {
    if (!fits(growth_bytes(v, more)))
      return false;
    grow(v, more);
    return true;
  }
  // Whether growing by `growth` bytes (the old buffer alive during the copy) stays within
  // the allowance.
  bool fits(std::size_t growth) {
    const std::size_t held = bytes() + growth;
    if (held > allowance)
      return false;
    peak_bytes = std::max(peak_bytes, held);
    return true;
  }

  void clear() {
    states.clear();
    candidates.clear();
    edges.clear();
    stuck.clear();
    edge_count = 0;
    expanded = 0;
    error = nullptr;
  }
};

struct StopEnumeration {};

constexpr std::size_t parallel_threshold = 4096;
constexpr std::size_t merge_prefetch_distance = 8;
constexpr std::size_t start_batch = 256;

std::uint32_t timed_bit(std::uint32_t duration) {
  return duration ? Edge::timed_bit : 0u;
}

} // namespace

Exploration explore(const tioa::SuccessorGenerator& generator, const tioa::StartSet& start,
                    const ExploreOptions& options, const ExploreHooks& hooks) {
  const std::uint32_t words = generator.words();
  const Limits& limits = options.limits;
  Exploration ex(words);
  ex.threads = options.threads == 0 ? 1 : options.threads;
  Progress progress(options.progress, options.task.empty() ? "exploring" : options.task);
  bool stopped = false;
  auto stop = [&](StopReason reason) {
    ex.stop = reason;
    stopped = true;
  };
  // At the state limit, a state that is not stored yet ends the run (incomplete); so a
  // space of exactly max_states states still finishes.
  auto at_state_limit = [&](const Word* state, std::uint64_t hash) {
    return limits.max_states && ex.store.size() >= limits.max_states && !ex.store.find(state, hash);
  };
  // The limit counts the store, the parents, the edges, the frontiers and the workers'
  // level buffers. It holds at every growth: a buffer grows only when what is held plus
  // the new buffer (the old one is alive while it is copied) stays within the limit.
  std::vector<Worker> workers(ex.threads, Worker(words));
  std::vector<StateId> frontier, next;
  auto memory_bytes = [&] {
    std::size_t bytes =
        ex.memory_bytes() + (frontier.capacity() + next.capacity()) * sizeof(StateId);
    for (const Worker& w : workers)
      bytes += w.bytes();
    return bytes;
  };
  // Whether the run may grow by `growth` bytes; else it stops on the memory limit.
  auto fits = [&](std::size_t growth) {
    if (growth == 0)
      return true;
    const std::size_t held = memory_bytes() + growth;
    if (limits.max_memory_bytes && held > limits.max_memory_bytes) {
      stop(StopReason::memory_limit);
      return false;
    }
    ex.peak_memory_bytes = std::max(ex.peak_memory_bytes, held);
    return true;
  };
  auto grow_within = [&](auto& v, std::size_t more) {
    if (!fits(growth_bytes(v, more)))
      return false;
    grow(v, more);
    return true;
  };
  // Room for one more state in the store, its parent, its place in `level` and its edge.
  auto room_to_insert = [&](std::vector<StateId>& level) {
    return fits(ex.store.growth_bytes()) && grow_within(ex.parent, 1) && grow_within(level, 1) &&
           (!hooks.record_edges || grow_within(ex.edge_list, 1));
  };
  auto check_time_and_memory = [&] {
    if (limits.max_seconds > 0 && progress.elapsed() > limits.max_seconds)
      stop(StopReason::time_limit);
    else if (limits.max_memory_bytes && memory_bytes() > limits.max_memory_bytes)
      stop(StopReason::memory_limit);
  };

  // Level 0: the start states, inserted in batches whose slots are prefetched first.
  std::vector<Word> buffer(words + 1, 0), representative(words + 1, 0);
  std::vector<Word> batch;
  std::vector<std::uint64_t> batch_hashes;
  auto insert_batch = [&] {
    for (std::size_t b = 0; b < batch_hashes.size(); ++b)
      ex.store.prefetch(batch_hashes[b]);
    for (std::size_t b = 0; b < batch_hashes.size() && !stopped; ++b) {
      const Word* state = batch.data() + b * words;
      if (at_state_limit(state, batch_hashes[b])) {
        stop(StopReason::state_limit);
        break;
      }
      if (!room_to_insert(frontier))
        break;
      const auto [id, fresh] = ex.store.insert(state, batch_hashes[b]);
      if (!fresh)
        continue;
      ex.parent.push_back(no_parent);
      ++ex.start_states;
      frontier.push_back(id);
      if (hooks.target && hooks.target(state)) {
        ex.found = id;
        stop(StopReason::found);
      }
    }
    batch.clear();
    batch_hashes.clear();
    if (!stopped)
      check_time_and_memory();
    progress.update(ex.store.size(), frontier.size(), 0);
  };
  try {
    start.enumerate(buffer.data(), 0, [&] {
      const Word* state = buffer.data();
      if (hooks.canonical) { // on a copy: the enumeration goes on from `buffer`
        std::copy(buffer.begin(), buffer.end(), representative.begin());
        hooks.canonical(representative.data());
        state = representative.data();
      }
      batch.insert(batch.end(), state, state + words);
      batch_hashes.push_back(hash_state(state, words));
      if (batch_hashes.size() == start_batch) {
        insert_batch();
        if (stopped)
          throw StopEnumeration{};
      }
    });
    insert_batch();
  } catch (const StopEnumeration&) {
  }

  for (auto& w : workers) {
    w.scratch.assign(words + 1, 0);
    w.canonical.assign(words + 1, 0);
  }
  std::atomic<bool> out_of_time{false}, out_of_memory{false};

  std::size_t used = 1; // threads expanding the current level
  auto expand_chunk = [&](Worker& w, std::size_t begin, std::size_t end) {
    try {
      for (std::size_t i = begin; i < end; ++i) {
        if (((i - begin) & 1023) == 1023) {
          if (&w == &workers.front()) // only the calling thread draws progress
            progress.update(ex.store.size(), frontier.size() - (i - begin) * used, ex.depth);
          if (limits.max_seconds > 0) {
            if (out_of_time.load(std::memory_order_relaxed))
              return;
            if (progress.elapsed() > limits.max_seconds) {
              out_of_time = true;
              return;
            }
          }
          if (out_of_memory.load(std::memory_order_relaxed))
            return;
        }
        const StateId id = frontier[i];
        const Word* state = ex.store.state(id);
        if (hooks.expand && !hooks.expand(state))
          continue;
        // Generate every successor first and prefetch its slot in the store, so that the
        // lookups below overlap their cache misses instead of waiting for each in turn.
        w.pending_states.clear();
        w.pending.clear();
        const std::size_t n = generator.successors(
            state, w.scratch.data(), [&](const Word* succ, const tioa::StepLabel& label) {
              if (hooks.canonical) {
                std::copy(succ, succ + words, w.canonical.begin());
                hooks.canonical(w.canonical.data());
                succ = w.canonical.data();
              }
              const std::uint64_t h = hash_state(succ, words);
              ex.store.prefetch(h);
              w.pending_states.push(succ);
              w.pending.push_back({h, generator.duration(label)});
            });
        // The successors pile up in the level buffers, which grow only within this
        // worker's share of the memory left.
        if (!w.make_room(n, hooks.record_edges)) {
          out_of_memory = true;
          return;
        }
        ++w.expanded;
        for (std::size_t k = 0; k < n; ++k) {
          const Word* succ = w.pending_states[k];
          const Pending& p = w.pending[k];
          if (const auto known = ex.store.find(succ, p.hash)) {
            if (hooks.record_edges)
              w.edges.push_back({id, *known | timed_bit(p.duration)});
            continue;
          }
          w.states.push(succ);
          w.candidates.push_back({p.hash, id, static_cast<std::uint8_t>(p.duration),
                                  hooks.target && hooks.target(succ)});
        }
        w.edge_count += n;
        if (n == 0)
          w.stuck.push_back(id);
      }
    } catch (...) {
      w.error = std::current_exception();
    }
  };

  while (!frontier.empty() && !stopped) {
    // Phase 1: expand.
    const std::size_t n = frontier.size();
    used = n < parallel_threshold ? 1 : workers.size();
    for (std::size_t t = 0; t < used; ++t)
      workers[t].clear();
    // The store and the frontiers do not change while the level is expanded: each worker
    // may add an equal share of the memory left.
    const std::size_t held = memory_bytes();
    if (limits.max_memory_bytes) {
      const std::size_t left = held < limits.max_memory_bytes ? limits.max_memory_bytes - held : 0;
      for (std::size_t t = 0; t < used; ++t)
        workers[t].allowance = workers[t].bytes() + left / used;
    }
    for (std::size_t t = 0; t < used; ++t)
      workers[t].peak_bytes = workers[t].level_start_bytes = workers[t].bytes();
    std::vector<std::thread> threads;
    for (std::size_t t = 1; t < used; ++t)
      threads.emplace_back(expand_chunk, std::ref(workers[t]), n * t / used, n * (t + 1) / used);
    expand_chunk(workers[0], 0, n / used);
    for (auto& th : threads)
      th.join();
    std::size_t level_peak = held;
    for (std::size_t t = 0; t < used; ++t) {
      if (workers[t].error)
        std::rethrow_exception(workers[t].error);
      level_peak += workers[t].peak_bytes - workers[t].level_start_bytes;
    }
    ex.peak_memory_bytes = std::max(ex.peak_memory_bytes, level_peak);

    // Phase 2: merge, in frontier order.
    next.clear();
    // The whole level was expanded, so its counts go in whole, whatever stops the merge:
    // they are then the same for every thread count.
    for (std::size_t t = 0; t < used; ++t) {
      ex.edges += workers[t].edge_count;
      ex.expanded += workers[t].expanded;
    }
    for (std::size_t t = 0; t < used && !stopped; ++t) {
      const Worker& w = workers[t];
      if (!grow_within(ex.stuck, w.stuck.size()) ||
          (hooks.record_edges && !grow_within(ex.edge_list, w.edges.size())))
        break;
      ex.stuck.insert(ex.stuck.end(), w.stuck.begin(), w.stuck.end());
      if (hooks.record_edges)
        ex.edge_list.insert(ex.edge_list.end(), w.edges.begin(), w.edges.end());
    }
    for (std::size_t t = 0; t < used && !stopped; ++t) {
      Worker& w = workers[t];
      for (std::size_t c = 0; c < w.candidates.size(); ++c) {
        if (c + merge_prefetch_distance < w.candidates.size())
          ex.store.prefetch(w.candidates[c + merge_prefetch_distance].hash);
        const Candidate& cand = w.candidates[c];
        const Word* succ = w.states[c];
        if (at_state_limit(succ, cand.hash)) {
          stop(StopReason::state_limit);
          break;
        }
        if (!room_to_insert(next))
          break;
        const auto [id, fresh] = ex.store.insert(succ, cand.hash);
        if (hooks.record_edges)
          ex.edge_list.push_back({cand.from, id | timed_bit(cand.duration)});
        if (!fresh)
          continue;
        ex.parent.push_back(cand.from);
        next.push_back(id);
        if (cand.target) {
          ex.found = id;
          stop(StopReason::found);
          break;
        }
      }
    }
    if (out_of_time)
      stop(StopReason::time_limit);
    else if (out_of_memory)
      stop(StopReason::memory_limit);
    if (!stopped)
      check_time_and_memory();
    ex.peak_memory_bytes = std::max(ex.peak_memory_bytes, memory_bytes());
    frontier.swap(next);
    ++ex.depth;
    progress.update(ex.store.size(), frontier.size(), ex.depth);
  }
  ex.seconds = progress.elapsed();
  return ex;
}

} // namespace checker
