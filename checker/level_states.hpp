#pragma once
// The full states of a run on the fingerprint store (fingerprint.hpp), whose store holds
// fingerprints only: those of the frontier being expanded and those of the level being
// built, two levels and no more. Each is indexed by state id from its level's first id.
//
// A narrow state (fewer than four words) is kept as it is, at its id's place in an array
// of the level. A wider one is kept packed, as its difference from a reference state (the
// first state put, a start state): a mask of the words that differ, then those words XOR
// the reference's.
//
// The states of a model with wide states differ from a start state in few words (the
// empty places of its queues stay as they start): vn-emulation's 43-word states of three
// nodes keep about 11.5 words. Each writer (a worker, by its index) appends to an arena of
// its own, and an id's place in the level is one word (which arena, where), so that a
// level is renumbered by moving those words, not the states.
//
// The workers of a level put the states they insert concurrently (put(), each at its own
// id and in its own arena): the level being built has places for every id the store may
// hand out before it says `full` (reserve() with the store's id limit, while no worker
// runs: at the start of the level and at the growth gate), and a writer makes room in its
// arena before it puts (make_room(), within its share of the memory). The bytes held
// count the places and the arenas, as the exact store counts its arena's.

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
  explicit LevelStates(std::uint32_t words)
      : words_(words), masks_(words >= packed_from ? (words + 63) / 64 : 0), reference_(words, 0) {}

  std::uint32_t words() const { return words_; }

  // Arenas for `writers` writers (0 .. writers - 1); before anything is put.
  void set_writers(std::size_t writers) {
    frontier_.arenas.resize(writers);
    building_.arenas.resize(writers);
  }

  // A state of the frontier (ids frontier_first().. frontier_first() + frontier size - 1),
  // unpacked into `out` (words() words), which it returns.
  const Word* frontier(StateId id, Word* out) const {
    if (!packed())
      return frontier_.raw.data() + std::size_t{id - frontier_first_} * words_;
    unpack(frontier_, id - frontier_first_, out);
    return out;
  }
  StateId frontier_first() const { return frontier_first_; }
  // A state of the level being built, unpacked into `out`.
  void built(StateId id, Word* out) const {
    if (!packed())
      std::copy_n(building_.raw.data() + std::size_t{id - first_} * words_, words_, out);
    else
      unpack(building_, id - first_, out);
  }
  StateId first() const { return first_; }

  // Places for the states of the level being built with ids below `end`; while nobody puts.
  void reserve(std::uint64_t end) {
    if (end <= first_ + room_)
      return;
    room_ = end - first_;
    if (packed())
      building_.place.reserve(room_);
    else
      building_.raw.reserve(room_ * words_);
  }
  // The bytes reserve(end) adds to bytes().
  std::size_t reserve_bytes(std::uint64_t end) const {
    return end <= first_ + room_ ? 0 : (end - first_ - room_) * place_bytes();
  }

  // Room in `writer`'s arena of the level being built for `states` more states (at most
  // this many words each: packed_words()), and the bytes that adds to bytes().
  std::size_t growth_bytes(std::size_t writer, std::size_t states) const {
    return packed() ? building_.arenas[writer].growth_bytes(states * packed_words()) : 0;
  }
  void make_room(std::size_t writer, std::size_t states) {
    if (packed())
      building_.arenas[writer].grow(states * packed_words());
  }
  // What `writer`'s arena of the level being built holds.
  std::size_t writer_bytes(std::size_t writer) const {
    return building_.arenas[writer].capacity() * sizeof(Word);
  }

  // The state with this id (below the reserved end), of the level being built, into
  // `writer`'s arena, which has room for it (make_room()). The first state put is the
  // reference (a start state, put alone).
  void put(StateId id, const Word* state, std::size_t writer) {
    if (!has_reference_) {
      std::copy_n(state, words_, reference_.data());
      has_reference_ = true;
    }
    if (!packed()) {
      std::copy_n(state, words_, building_.raw.data() + std::size_t{id - first_} * words_);
      return;
    }
    MappedVector<Word>& arena = building_.arenas[writer];
    const std::size_t at = arena.size();
    building_.place[id - first_] = (std::uint64_t{writer} << offset_bits) | at;
    arena.resize(at + masks_);
    for (std::uint32_t m = 0; m < masks_; ++m)
      arena[at + m] = 0;
    for (std::uint32_t i = 0; i < words_; ++i) {
      const Word difference = state[i] ^ reference_[i];
      if (difference == 0)
        continue;
      arena[at + i / 64] |= Word{1} << (i % 64);
      arena.push_back(difference);
    }
  }

  // The level being built, `count` ids with its holes, is renumbered (StateStore::reorder):
  // the state `order[i]` gets the id first() + i.
  void reorder(std::span<const StateId> order, std::uint64_t count) {
    if (!packed()) {
      const std::vector<Word> before(building_.raw.data(), building_.raw.data() + count * words_);
      for (std::size_t i = 0; i < order.size(); ++i)
        std::copy_n(before.data() + std::size_t{order[i] - first_} * words_, words_,
                    building_.raw.data() + i * words_);
      return;
    }
    const std::vector<std::uint64_t> before(building_.place.data(), building_.place.data() + count);
    for (std::size_t i = 0; i < order.size(); ++i)
      building_.place[i] = before[order[i] - first_];
  }
  // What reorder() allocates.
  std::size_t reorder_bytes(std::uint64_t count) const { return count * place_bytes(); }

  // The level built becomes the frontier (`count` states); the next level starts at id
  // first() + count. The frontier's buffers are used again for it.
  void next_level(std::uint64_t count) {
    std::swap(frontier_, building_);
    for (MappedVector<Word>& arena : building_.arenas)
      arena.clear();
    frontier_first_ = first_;
    frontier_size_ = count;
    first_ = static_cast<StateId>(first_ + count);
    room_ = 0;
  }

  // What the two levels hold: the frontier's places, the places reserved for the level
  // being built, and the arenas of both (a narrow state's place is the state).
  std::size_t bytes() const {
    std::size_t arenas = 0;
    for (const Level* level : {&frontier_, &building_})
      for (const MappedVector<Word>& arena : level->arenas)
        arenas += arena.capacity() * sizeof(Word);
    return (frontier_size_ + room_) * place_bytes() + arenas;
  }

private:
  // A level: per id from its first, the place of its packed state (writer << offset_bits |
  // the word where it starts in that writer's arena), and the arenas.
  struct Level {
    MappedArray<std::uint64_t> place;
    std::vector<MappedVector<Word>> arenas;
    MappedArray<Word> raw; // narrow states, words() per id
  };
  static constexpr int offset_bits = 44;
  // States of fewer words are kept as they are: a mask word would save too little.
  static constexpr std::uint32_t packed_from = 4;

  bool packed() const { return masks_ != 0; }
  // What one id takes in the level's array.
  std::size_t place_bytes() const {
    return packed() ? sizeof(std::uint64_t) : std::size_t{words_} * sizeof(Word);
  }
  // The most words a packed state takes.
  std::uint32_t packed_words() const { return masks_ + words_; }

  void unpack(const Level& level, std::uint64_t index, Word* out) const {
    const std::uint64_t place = level.place[index];
    const Word* packed = level.arenas[place >> offset_bits].data() +
                         (place & ((std::uint64_t{1} << offset_bits) - 1));
    const Word* next = packed + masks_;
    for (std::uint32_t i = 0; i < words_; ++i)
      out[i] = reference_[i] ^ ((packed[i / 64] >> (i % 64) & 1) ? *next++ : 0);
  }

  std::uint32_t words_, masks_;
  std::vector<Word> reference_;
  bool has_reference_ = false;
  Level frontier_, building_;
  StateId frontier_first_ = 0, first_ = 0;
  std::uint64_t frontier_size_ = 0;
  std::uint64_t room_ = 0; // reserved places of the level being built
};

} // namespace checker
