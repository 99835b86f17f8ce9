#pragma once
// Breadth-first exploration, level by level, in two phases per level:
//  1. expand (parallel): the frontier is cut into contiguous chunks, one per thread; each
//     thread generates the successors of its states, drops those already stored (the
//     store is only read in this phase) and keeps the rest as candidates;
//  2. merge (one thread): candidates are inserted chunk by chunk, in frontier order.
// Ids, parents, counts and the first target found are therefore the same for every
// thread count as for a plain sequential BFS, and traces are shortest in steps.

#include <functional>
#include <optional>
#include <vector>

#include "checker/options.hpp"
#include "checker/state_store.hpp"
#include "tioa/start_set.hpp"
#include "tioa/successors.hpp"

namespace checker {

inline constexpr StateId no_parent = 0xffffffffu;

// A stored edge; the top bit of `to` says the step took one unit of time.
struct Edge {
  StateId from;
  std::uint32_t to;
  static constexpr std::uint32_t timed_bit = 0x80000000u;
  StateId target() const { return to & ~timed_bit; }
  std::uint32_t duration() const { return (to & timed_bit) ? 1 : 0; }
};

// Optional hooks; an empty hook costs nothing.
struct ExploreHooks {
  std::function<bool(const Word*)> expand; // expand this state? (default: yes)
  std::function<bool(const Word*)> target; // stop at the first stored state where true
  // Replaces every state (start or successor) by its representative before it is looked
  // up, so the store holds one state per class. Sound only when states of one class have
  // successors of the same classes (a bisimulation); parents then link representatives,
  // which need not replay as a trace of the automaton.
  std::function<void(Word*)> canonical;
  bool record_edges = false;
};

struct Exploration {
  explicit Exploration(std::uint32_t words) : store(words) {}

  StateStore store;
  std::vector<StateId> parent; // no_parent for start states
  std::uint64_t start_states = 0;
  std::uint64_t edges = 0;
  std::uint64_t expanded = 0;
  std::uint32_t depth = 0; // levels completed
  StopReason stop = StopReason::finished;
  std::optional<StateId> found; // the first target state
  std::vector<StateId> stuck;   // expanded states with no successor at all
  std::vector<Edge> edge_list;  // when record_edges
  double seconds = 0;
  unsigned threads = 1;
  // The most memory held at once as the memory limit counts it, reallocations included
  // (their old and new buffers together).
  std::size_t peak_memory_bytes = 0;

  bool complete() const { return stop == StopReason::finished || stop == StopReason::found; }
  std::size_t memory_bytes() const {
    return store.memory_bytes() + parent.capacity() * sizeof(StateId) +
           stuck.capacity() * sizeof(StateId) + edge_list.capacity() * sizeof(Edge);
  }
};

Exploration explore(const tioa::SuccessorGenerator& generator, const tioa::StartSet& start,
                    const ExploreOptions& options, const ExploreHooks& hooks = {});

} // namespace checker
