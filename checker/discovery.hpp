#pragma once
// Which step found each state of the level being built first. A step is keyed by
//
//   key = parent id << 32 | the step's index among the parent's successors
//
// and since the frontier is a range of ids in breadth-first order, a sequential
// breadth-first search inserts the states of a level in the order of their smallest keys,
// and takes each one's parent from it. When several workers insert concurrently, each
// new state keeps the smallest key any worker found it with, and the level is renumbered
// in key order afterwards (level_end.hpp): ids, parents and traces are then those of one
// worker, whatever the number of workers.

#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "checker/mapped_memory.hpp"
#include "checker/state_store.hpp"

namespace checker {

class Discovery {
public:
  static std::uint64_t key(StateId parent, std::uint64_t step) {
    return (std::uint64_t{parent} << 32) | step;
  }
  static StateId parent_of(std::uint64_t key) { return static_cast<StateId>(key >> 32); }

  // A new level: its states get ids from `first` on.
  void begin(StateId first) {
    first_ = first;
    slots_valid_ = true;
  }
  StateId first() const { return first_; }

  // Room for the keys of every id below `end`; while nobody writes keys.
  void make_room(std::uint64_t end) {
    if (end > first_) {
      keys_.reserve(end - first_);
      slots_.reserve(end - first_);
    }
  }
  // What the keys of the states up to `size` (the store's) take: this much per state.
  static constexpr std::size_t bytes_per_state = sizeof(std::uint64_t) + sizeof(std::uint32_t);
  // The buffers of the level's end come on top (order_bytes()).
  std::size_t bytes(std::uint64_t size) const {
    return (size > first_ ? (size - first_) * bytes_per_state : 0) + order_bytes();
  }

  // A new state, found first by the step `key`.
  void found(StateId id, std::uint64_t key) { keys_[id - first_] = key; }
  // ... placed in the store's table at `slot` (kept when the level is to be renumbered).
  void placed(StateId id, std::uint32_t slot) { slots_[id - first_] = slot; }
  // Where the store's table holds the level's states: placed() at their insertion, and
  // again when a new table takes them (StateStore::make_room's `placed`, which the
  // explorer passes while several workers build the level). A table that grew without
  // telling (one worker: no renumbering needs them) calls forget_slots(): none then.
  const std::uint32_t* slots() const { return slots_valid_ ? slots_.data() : nullptr; }
  void forget_slots() { slots_valid_ = false; }
  // A state of this level found again: it keeps the smaller key. `concurrent`: other
  // threads may do the same at once.
  void found_again(StateId id, std::uint64_t key, bool concurrent) {
    std::uint64_t& slot = keys_[id - first_];
    if (!concurrent) {
      slot = std::min(slot, key);
      return;
    }
    std::atomic_ref<std::uint64_t> shared(slot);
    std::uint64_t seen = shared.load(std::memory_order_relaxed);
    while (key < seen && !shared.compare_exchange_weak(seen, key, std::memory_order_relaxed)) {
    }
  }
  std::uint64_t key_of(StateId id) const { return keys_[id - first_]; }
  // The keys' memory, for a level's renumbering to move its states through once every
  // key has been read (order() and the parents taken): `words` words, or empty when it
  // holds fewer. Its pages were written by this level already, so using it costs no
  // fresh page, as a new buffer would at every level. The keys are garbage afterwards.
  std::span<Word> spent_keys(std::uint64_t words) {
    return words <= keys_.capacity() ? std::span<Word>(keys_.data(), words) : std::span<Word>();
  }
  // Ids from first on that no state has (yet): a worker's id block when it takes it.
  void holes(std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t id = begin; id < end; ++id)
      keys_[id - first_] = hole;
  }
  static constexpr std::uint64_t hole = ~std::uint64_t{0};

  // The states among ids first.. first + count - 1 (holes left out) in key order, given
  // that their parents are in [parents_begin, parents_end), shared by `threads` threads
  // (the same order for any number: the keys are distinct). In the discovery's own
  // buffer, valid until the next order(), dense_order() or new_ids(). `parents`, when
  // given, gets the parent of each state of the order, at its place.
  std::span<const StateId> order(std::uint64_t count, StateId parents_begin, StateId parents_end,
                                 std::uint32_t threads = 1, StateId* parents = nullptr);
  // The states among ids first.. first + count - 1 with the holes filled by the last
  // states, the others where they are: an order that moves few states, in no key order.
  // `parents` as in order().
  std::span<const StateId> dense_order(std::uint64_t count, StateId* parents = nullptr);
  // After order() or dense_order() of `count` ids: the new id of the state with id
  // first + t at [t], first + its place in the order (a hole's entry is garbage). Valid
  // until the next order(), dense_order() or new_ids().
  std::span<const StateId> new_ids(std::span<const StateId> order, std::uint64_t count,
                                   std::uint32_t threads = 1);
  // What the buffers of order() and new_ids() take, and what they need beyond that for a
  // level of `count` ids. They are kept from level to level, so that their pages are
  // written in once (for the largest level), not at every level.
  std::size_t order_bytes() const { return order_.bytes() + staged_.bytes(); }
  std::size_t order_growth_bytes(std::uint64_t count) const {
    const std::size_t needed = 2 * count * sizeof(StateId);
    return needed > order_bytes() ? needed - order_bytes() : 0;
  }

private:
  StateId first_ = 0;
  MappedArray<std::uint64_t> keys_;
  MappedArray<std::uint32_t> slots_;
  bool slots_valid_ = true;
  // order()'s result, and the states it stages by bucket of parents (then new_ids()).
  MappedArray<StateId> order_, staged_;
};

} // namespace checker
