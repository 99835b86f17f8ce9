#pragma once
// The visited-state store. Each state is held once, in the arena, in id order (ids are
// dense, in insertion order), so per-state data lives in arrays indexed by id and
// expanding a level reads the arena sequentially. The hash table holds 32-bit slots:
//
//   slot = tag << m | (id + 1)      with 2^m slots; 0 is an empty slot
//
// The id takes the low m bits (the table is at most three quarters full, so id + 1 <
// 2^m - 1), and the 32 - m bits left keep a tag of the hash, so that a lookup compares
// the arena's state only when the tags agree. The home slot is the hash's low m bits; the
// tag comes from its high bits. At 2^24 slots (up to 12.5 million states) a slot costs
// 5.3 to 10.7 bytes per state, with 8 tag bits.
//
// Growth never holds two tables: the old one is given back first and the new one, twice
// as big, is filled again from the arena. The arena and the table are mapped memory
// (mapped_memory.hpp), which grows without a copy.
//
// find() may run on several threads at once while nothing inserts; insert() is for one
// thread at a time.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>

#include "checker/mapped_memory.hpp"
#include "tioa/state_hash.hpp"
#include "tioa/variables.hpp"

namespace checker {

using tioa::Word;
using StateId = std::uint32_t;

using tioa::hash_state; // tioa/state_hash.hpp

class StateStore {
public:
  explicit StateStore(std::uint32_t words);

  std::uint32_t words() const { return words_; }
  std::uint64_t size() const { return count_; }
  const Word* state(StateId id) const { return arena_.data() + std::size_t{id} * words_; }

  // Starts loading the slot where a state with this hash would be.
  void prefetch(std::uint64_t hash) const { __builtin_prefetch(table_.data() + (hash & mask_)); }

  std::optional<StateId> find(const Word* state, std::uint64_t hash) const {
    const std::uint64_t tag = tag_of(hash);
    for (std::uint64_t at = hash & mask_;; at = (at + 1) & mask_) {
      const std::uint64_t slot = table_[at];
      if (slot == 0)
        return std::nullopt;
      if ((slot >> bits_) == tag) {
        const StateId id = static_cast<StateId>((slot & mask_) - 1);
        if (same(this->state(id), state))
          return id;
      }
    }
  }

  // The id of the state, and whether it was new.
  std::pair<StateId, bool> insert(const Word* state, std::uint64_t hash);

  // What the store counts as held: the table and the arena.
  std::size_t memory_bytes() const { return table_.bytes() + arena_.capacity() * sizeof(Word); }

  // The bytes memory_bytes() grows by at the next insert() (0 when it does not grow). The
  // table's old buffer is given back before the new one is taken.
  std::size_t growth_bytes() const {
    std::size_t bytes = arena_.growth_bytes(words_);
    if (needs_bigger_table(count_ + 1))
      bytes += table_.bytes();
    return bytes;
  }

  // Three quarters of the largest table (2^32 slots).
  static constexpr std::uint64_t max_states = 0xc0000000u;

private:
  bool same(const Word* a, const Word* b) const {
    for (std::uint32_t i = 0; i < words_; ++i)
      if (a[i] != b[i])
        return false;
    return true;
  }
  std::uint64_t tag_of(std::uint64_t hash) const { return bits_ < 32 ? hash >> (32 + bits_) : 0; }
  bool needs_bigger_table(std::uint64_t states) const { return states * 4 > (mask_ + 1) * 3; }
  // The table with 2^bits slots, filled from the arena.
  void rebuild(std::uint32_t bits);

  std::uint32_t words_;
  std::uint32_t bits_ = 0; // m: 2^m slots
  std::uint64_t mask_ = 0; // 2^m - 1
  std::uint64_t count_ = 0;
  MappedVector<Word> arena_;
  MappedArray<std::uint32_t> table_;
};

} // namespace checker
