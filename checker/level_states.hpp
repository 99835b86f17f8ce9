#pragma once
// The full states of a run on the fingerprint store (fingerprint.hpp), whose store holds
// fingerprints only: those of the frontier being expanded and those of the level being
// built, two levels and no more. Each is indexed by state id from its level's first id.
//
// The workers of a level write the states they insert concurrently (put(), each at its
// own id), so the level being built has room for every id the store may hand out before
// it says `full` (reserve() with the store's id limit, while no worker runs: at the start
// of the level and at the growth gate). The bytes held count that room, as the exact
// store counts its arena's.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "checker/mapped_memory.hpp"
#include "checker/state_store.hpp"

namespace checker {

class LevelStates {
public:
  explicit LevelStates(std::uint32_t words) : words_(words) {}

  std::uint32_t words() const { return words_; }

  // A state of the frontier (ids frontier_first().. frontier_first() + frontier size - 1).
  const Word* frontier(StateId id) const {
    return frontier_.data() + std::size_t{id - frontier_first_} * words_;
  }
  StateId frontier_first() const { return frontier_first_; }
  // A state of the level being built.
  const Word* built(StateId id) const {
    return building_.data() + std::size_t{id - first_} * words_;
  }
  StateId first() const { return first_; }

  // Room for the states of the level being built with ids below `end`; while nobody puts.
  void reserve(std::uint64_t end) {
    if (end <= first_ + room_)
      return;
    room_ = end - first_;
    building_.reserve(room_ * words_);
  }
  // The bytes reserve(end) adds to bytes().
  std::size_t reserve_bytes(std::uint64_t end) const {
    return end <= first_ + room_ ? 0 : (end - first_ - room_) * words_ * sizeof(Word);
  }
  // The state with this id (below the reserved end), of the level being built.
  void put(StateId id, const Word* state) {
    std::copy_n(state, words_, building_.data() + std::size_t{id - first_} * words_);
  }

  // The level being built, `count` ids with its holes, is renumbered (StateStore::reorder):
  // the state `order[i]` gets the id first() + i.
  void reorder(std::span<const StateId> order, std::uint64_t count) {
    const std::vector<Word> before(building_.data(), building_.data() + count * words_);
    for (std::size_t i = 0; i < order.size(); ++i)
      std::copy_n(before.data() + std::size_t{order[i] - first_} * words_, words_,
                  building_.data() + i * words_);
  }
  // What reorder() allocates.
  std::size_t reorder_bytes(std::uint64_t count) const { return count * words_ * sizeof(Word); }

  // The level built becomes the frontier (`count` states); the next level starts at id
  // first() + count. The frontier's buffer is used again for it.
  void next_level(std::uint64_t count) {
    std::swap(frontier_, building_);
    frontier_first_ = first_;
    frontier_size_ = count;
    first_ = static_cast<StateId>(first_ + count);
    room_ = 0;
  }

  // What the two levels hold: the frontier's states and the room of the level being built.
  std::size_t bytes() const { return (frontier_size_ + room_) * words_ * sizeof(Word); }

private:
  std::uint32_t words_;
  MappedArray<Word> frontier_, building_;
  StateId frontier_first_ = 0, first_ = 0;
  std::uint64_t frontier_size_ = 0;
  std::uint64_t room_ = 0; // reserved states of the level being built
};

} // namespace checker
