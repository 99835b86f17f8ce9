#include "checker/state_store.hpp"

#include <algorithm>
#include <stdexcept>

namespace checker {

namespace {
constexpr std::uint64_t initial_slots = 1024;
}

StateStore::StateStore(std::uint32_t words) : words_(words), stride_(words + 1) {
  table_ = PageBuffer(initial_slots * stride_);
  mask_ = initial_slots - 1;
}

std::pair<StateId, bool> StateStore::insert(const Word* state, std::uint64_t hash) {
  if ((count_ + 1) * 2 > mask_ + 1)
    grow();
  const std::uint64_t tag = hash >> 32;
  std::uint64_t at = hash & mask_;
  for (;; at = (at + 1) & mask_) {
    const Word* slot = table_.data() + at * stride_;
    if (slot[0] == 0)
      break;
    if ((slot[0] >> 32) == tag && same(slot + 1, state))
      return {static_cast<StateId>((slot[0] & 0xffffffffu) - 1), false};
  }
  if (count_ >= max_states)
    throw std::length_error("state store is full (2^32 states)");
  const StateId id = static_cast<StateId>(count_++);
  const std::size_t end = std::size_t{id} * words_;
  if (end + words_ > arena_.size())
    arena_.resize(arena_growth(arena_.size(), words_));
  for (std::uint32_t i = 0; i < words_; ++i)
    arena_[end + i] = state[i];
  Word* slot = table_.data() + at * stride_;
  slot[0] = (tag << 32) | (std::uint64_t{id} + 1);
  for (std::uint32_t i = 0; i < words_; ++i)
    slot[1 + i] = state[i];
  return {id, true};
}

void StateStore::grow() {
  const std::uint64_t slots = (mask_ + 1) * 2;
  PageBuffer bigger(slots * stride_);
  const std::uint64_t mask = slots - 1;
  for (std::uint64_t old = 0; old <= mask_; ++old) {
    const Word* slot = table_.data() + old * stride_;
    if (slot[0] == 0)
      continue;
    std::uint64_t at = hash_state(slot + 1, words_) & mask;
    while (bigger.data()[at * stride_] != 0)
      at = (at + 1) & mask;
    for (std::uint32_t i = 0; i < stride_; ++i)
      bigger.data()[at * stride_ + i] = slot[i];
  }
  table_.swap(bigger);
  mask_ = mask;
}

} // namespace checker
