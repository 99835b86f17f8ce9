#pragma once
// What an exploration produces: the store of reached states with their parents, the
// counts, why it stopped, and (on request) its edges. See explorer.hpp.

#include <cstdint>
#include <optional>
#include <vector>

#include "checker/mapped_memory.hpp"
#include "checker/options.hpp"
#include "checker/state_store.hpp"

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

// The edge to `to` for a step of `duration` (0 or 1 quantum).
inline std::uint32_t edge_to(StateId to, std::uint32_t duration) {
  return to | (duration ? Edge::timed_bit : 0u);
}

struct Exploration {
  explicit Exploration(std::uint32_t words) : store(words) {}

  StateStore store;
  MappedVector<StateId> parent; // no_parent for start states
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
  bool reduction = false;           // zero-time steps reduced (zero_time_reduction.hpp)
  std::uint64_t reduced_states = 0; // states expanded with fewer steps than were enabled
  // The most memory held at once as the memory limit counts it, reallocations included
  // (their old and new buffers together).
  std::size_t peak_memory_bytes = 0;

  bool complete() const { return stop == StopReason::finished || stop == StopReason::found; }
  std::size_t memory_bytes() const {
    return store.memory_bytes() + parent.capacity() * sizeof(StateId) +
           stuck.capacity() * sizeof(StateId) + edge_list.capacity() * sizeof(Edge);
  }
};

} // namespace checker
