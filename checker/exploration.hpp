#pragma once
// What an exploration produces: the store of reached states with their parents, the
// counts, why it stopped, and (on request) its edges. See explorer.hpp.
//
// On the fingerprint store (fingerprint.hpp) `store` holds one fingerprint per state
// (store.words() is 1), not the states: only trace_to() (trace.hpp) may rebuild states,
// from the start set kept here, and the full states of the first target and of the
// first stuck state are kept.
//
// On the compressed store (state_tree.hpp) `store` holds one key per state too, and `tree`
// the parts the keys name: state() decodes a state from them (exact).

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "checker/mapped_memory.hpp"
#include "checker/options.hpp"
#include "checker/state_store.hpp"
#include "checker/state_tree.hpp"
#include "tioa/start_set.hpp"

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
  explicit Exploration(std::uint32_t words, StoreKind kind = StoreKind::exact)
      : store(kind == StoreKind::exact ? words : 1), state_words(words), store_kind(kind) {
    if (kind == StoreKind::compressed && words > 1) // (one word is its own key)
      tree = std::make_shared<StateTree>(words);
  }

  StateStore store;
  std::uint32_t state_words; // of a state (store.words() is 1 on the fingerprint store)
  StoreKind store_kind;
  // The compressed store's parts (shared by copies of the exploration, which read it only).
  std::shared_ptr<StateTree> tree;
  MappedVector<StateId> parent; // no_parent for start states
  std::uint64_t start_states = 0;
  std::uint64_t edges = 0;
  std::uint64_t expanded = 0;
  std::uint32_t depth = 0; // levels completed
  StopReason stop = StopReason::finished;
  std::optional<StateId> found; // the first target state
  std::vector<StateId> stuck;   // expanded states with no successor at all
  // The edges, when record_edges, in one compact form: the steps of the expanded state v
  // are edge_targets[edge_offsets[v] .. edge_offsets[v + 1]) (edge_to(): the target and
  // a timed bit), in the order the search took them. States not expanded (past
  // edge_offsets.size() - 1) have none, nor have the states of a level that a time or
  // memory limit or a stop from outside cut short (level_end.hpp).
  std::vector<std::uint64_t> edge_offsets{0};
  std::vector<std::uint32_t> edge_targets;
  double seconds = 0;
  unsigned threads = 1;
  bool reduction = false;           // zero-time steps reduced (zero_time_reduction.hpp)
  std::uint64_t reduced_states = 0; // states expanded with fewer steps than were enabled
  // The most memory held at once as the memory limit counts it, reallocations included
  // (their old and new buffers together).
  std::size_t peak_memory_bytes = 0;

  // The fingerprint store only: the start set (trace_to() enumerates it again), and the
  // full states of `found` and of stuck.front(), when there are such.
  std::optional<tioa::StartSet> start;
  std::vector<Word> found_state, first_stuck_state;

  bool fingerprints() const { return store_kind == StoreKind::fingerprint; }
  bool compressed() const { return store_kind == StoreKind::compressed; }

  // The state `id` (state_words words): in the store, or on the compressed store decoded
  // into `buffer`. Not on the fingerprint store, which keeps no states (trace.hpp).
  const Word* state(StateId id, std::vector<Word>& buffer) const;
  // The id of a stored state equal to `state` (state_words words), if there is one. Not on
  // the fingerprint store.
  std::optional<StateId> find(const Word* state) const;

  bool complete() const { return stop == StopReason::finished || stop == StopReason::found; }
  std::size_t memory_bytes() const {
    return store.memory_bytes() + (tree ? tree->memory_bytes() : 0) +
           parent.capacity() * sizeof(StateId) + stuck.capacity() * sizeof(StateId) +
           edge_offsets.capacity() * sizeof(std::uint64_t) +
           edge_targets.capacity() * sizeof(std::uint32_t);
  }
  // The steps recorded from `v` (edge_to() form).
  std::span<const std::uint32_t> steps_from(StateId v) const {
    if (std::size_t{v} + 1 >= edge_offsets.size())
      return {};
    return {edge_targets.data() + edge_offsets[v], edge_targets.data() + edge_offsets[v + 1]};
  }
};

// Reads an exploration's states one at a time, whatever its store: on the exact store a
// pointer into it, on the compressed store the state decoded into this reader's buffer,
// valid until its next read. A thread needs its own reader, and code that holds two states
// at once needs two.
class StateReader {
public:
  explicit StateReader(const Exploration& ex) : ex_(&ex) {}
  const Word* operator()(StateId id) { return ex_->state(id, buffer_); }

private:
  const Exploration* ex_;
  std::vector<Word> buffer_;
};

} // namespace checker
