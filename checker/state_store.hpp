#pragma once
// The visited-state store: an open-addressing hash table with linear probing whose slots
// hold the state itself (so a lookup costs one cache miss, not two), plus an arena with
// the states in id order (so per-state data lives in plain vectors indexed by id, and
// expanding state `id` reads the arena sequentially). Ids are dense, in insertion order.
//
// find() may run on several threads at once while nothing inserts; insert() is for one
// thread at a time (the explorer's merge phase).

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "checker/page_buffer.hpp"
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
  void prefetch(std::uint64_t hash) const {
    __builtin_prefetch(table_.data() + (hash & mask_) * stride_);
  }

  std::optional<StateId> find(const Word* state, std::uint64_t hash) const {
    const std::uint64_t tag = hash >> 32;
    for (std::uint64_t at = hash & mask_;; at = (at + 1) & mask_) {
      const Word* slot = table_.data() + at * stride_;
      if (slot[0] == 0)
        return std::nullopt;
      if ((slot[0] >> 32) == tag && same(slot + 1, state))
        return static_cast<StateId>((slot[0] & 0xffffffffu) - 1);
    }
  }

  // The id of the state, and whether it was new.
  std::pair<StateId, bool> insert(const Word* state, std::uint64_t hash);

  std::size_t memory_bytes() const { return arena_.capacity() * sizeof(Word) + table_.bytes(); }

  // The bytes the next insert() allocates when it grows the table or the arena (0 when it
  // does not). The old buffer stays alive while it is copied, so at that moment the store
  // holds memory_bytes() + growth_bytes().
  std::size_t growth_bytes() const {
    std::size_t bytes = 0;
    if ((count_ + 1) * 2 > mask_ + 1)
      bytes += 2 * table_.bytes();
    if ((count_ + 1) * words_ > arena_.size())
      bytes += arena_growth(arena_.size(), words_) * sizeof(Word);
    return bytes;
  }

  static constexpr std::uint64_t max_states = 0xfffffff0u;

private:
  bool same(const Word* a, const Word* b) const {
    for (std::uint32_t i = 0; i < words_; ++i)
      if (a[i] != b[i])
        return false;
    return true;
  }
  void grow();
  // The arena's size after it grows from `size` words: it doubles.
  static std::size_t arena_growth(std::size_t size, std::uint32_t words) {
    return std::max<std::size_t>(2 * size, std::size_t{1024} * words);
  }

  std::uint32_t words_;
  std::uint32_t stride_; // words per slot: tag << 32 | (id + 1), then the state
  std::uint64_t count_ = 0;
  std::uint64_t mask_ = 0;
  std::vector<Word> arena_; // grows by doubling; only the first count_ states are used
  PageBuffer table_;
};

} // namespace checker
