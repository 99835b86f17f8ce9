#include "checker/state_store.hpp"

#include <stdexcept>

namespace checker {

namespace {
constexpr std::uint32_t initial_bits = 10;
// States hashed ahead of the one placed while the table is filled again.
constexpr std::uint64_t rebuild_prefetch = 16;
} // namespace

StateStore::StateStore(std::uint32_t words) : words_(words) {
  rebuild(initial_bits);
}

std::pair<StateId, bool> StateStore::insert(const Word* state, std::uint64_t hash) {
  if (const auto known = find(state, hash))
    return {*known, false};
  if (count_ >= max_states)
    throw std::length_error("state store is full (3 * 2^30 states)");
  if (needs_bigger_table(count_ + 1))
    rebuild(bits_ + 1);
  const StateId id = static_cast<StateId>(count_++);
  arena_.grow(words_);
  for (std::uint32_t i = 0; i < words_; ++i)
    arena_.push_back(state[i]);
  std::uint64_t at = hash & mask_;
  while (table_[at] != 0)
    at = (at + 1) & mask_;
  table_[at] = static_cast<std::uint32_t>((tag_of(hash) << bits_) | (std::uint64_t{id} + 1));
  return {id, true};
}

void StateStore::rebuild(std::uint32_t bits) {
  table_.release();
  bits_ = bits;
  mask_ = (std::uint64_t{1} << bits) - 1;
  table_ = MappedArray<std::uint32_t>(mask_ + 1);
  std::uint64_t ahead[rebuild_prefetch];
  auto hash_of = [&](std::uint64_t id) {
    return hash_state(state(static_cast<StateId>(id)), words_);
  };
  for (std::uint64_t id = 0; id < std::min(count_, rebuild_prefetch); ++id)
    prefetch(ahead[id] = hash_of(id));
  for (std::uint64_t id = 0; id < count_; ++id) {
    const std::uint64_t hash = ahead[id % rebuild_prefetch];
    if (id + rebuild_prefetch < count_)
      prefetch(ahead[id % rebuild_prefetch] = hash_of(id + rebuild_prefetch));
    std::uint64_t at = hash & mask_;
    while (table_[at] != 0)
      at = (at + 1) & mask_;
    table_[at] = static_cast<std::uint32_t>((tag_of(hash) << bits_) | (id + 1));
  }
}

} // namespace checker
