#pragma once
// The visited-state store: states packed one after another in an arena (no allocation
// per state) and an open-addressing hash table with linear probing whose slots hold a
// 32-bit hash tag and the state's id. Ids are dense, in insertion order, so per-state
// data (parents, flags) lives in plain vectors indexed by id.
//
// find() may run on several threads at once while nothing inserts; insert() is for one
// thread at a time (the explorer's merge phase).

#include <cstdint>
#include <optional>
#include <vector>

#include "tioa/variables.hpp"

namespace checker {

using tioa::Word;
using StateId = std::uint32_t;

// A multiply-xorshift hash over the words, finished with the SplitMix64 mixer.
inline std::uint64_t hash_state(const Word* state, std::uint32_t words) {
  std::uint64_t h = 0x243f6a8885a308d3ull;
  for (std::uint32_t i = 0; i < words; ++i)
    h = (h ^ (h >> 31) ^ state[i]) * 0x9e3779b97f4a7c15ull;
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

class StateStore {
public:
  explicit StateStore(std::uint32_t words);

  std::uint32_t words() const { return words_; }
  std::uint64_t size() const { return count_; }
  const Word* state(StateId id) const { return arena_.data() + std::size_t{id} * words_; }

  std::optional<StateId> find(const Word* state, std::uint64_t hash) const;
  // The id of the state, and whether it was new.
  std::pair<StateId, bool> insert(const Word* state, std::uint64_t hash);

  std::size_t memory_bytes() const {
    return arena_.capacity() * sizeof(Word) + table_.capacity() * sizeof(std::uint64_t);
  }

  static constexpr std::uint64_t max_states = 0xfffffff0u;

private:
  void grow();
  bool equal(StateId id, const Word* state) const;

  std::uint32_t words_;
  std::uint64_t count_ = 0;
  std::vector<Word> arena_;
  std::vector<std::uint64_t> table_; // 0: empty; else tag << 32 | (id + 1)
  std::uint64_t mask_ = 0;
};

} // namespace checker
