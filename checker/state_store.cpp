#include "checker/state_store.hpp"

#include <stdexcept>

namespace checker {

StateStore::StateStore(std::uint32_t words) : words_(words) {
  table_.assign(1024, 0);
  mask_ = table_.size() - 1;
}

bool StateStore::equal(StateId id, const Word* state) const {
  const Word* stored = this->state(id);
  for (std::uint32_t i = 0; i < words_; ++i)
    if (stored[i] != state[i])
      return false;
  return true;
}

std::optional<StateId> StateStore::find(const Word* state, std::uint64_t hash) const {
  const std::uint64_t tag = hash >> 32;
  for (std::uint64_t at = hash & mask_;; at = (at + 1) & mask_) {
    const std::uint64_t slot = table_[at];
    if (slot == 0)
      return std::nullopt;
    if ((slot >> 32) == tag) {
      const StateId id = static_cast<StateId>((slot & 0xffffffffu) - 1);
      if (equal(id, state))
        return id;
    }
  }
}

std::pair<StateId, bool> StateStore::insert(const Word* state, std::uint64_t hash) {
  if ((count_ + 1) * 2 > table_.size())
    grow();
  const std::uint64_t tag = hash >> 32;
  std::uint64_t at = hash & mask_;
  for (;; at = (at + 1) & mask_) {
    const std::uint64_t slot = table_[at];
    if (slot == 0)
      break;
    if ((slot >> 32) == tag) {
      const StateId id = static_cast<StateId>((slot & 0xffffffffu) - 1);
      if (equal(id, state))
        return {id, false};
    }
  }
  if (count_ >= max_states)
    throw std::length_error("state store is full (2^32 states)");
  const StateId id = static_cast<StateId>(count_++);
  arena_.insert(arena_.end(), state, state + words_);
  table_[at] = (tag << 32) | (std::uint64_t{id} + 1);
  return {id, true};
}

void StateStore::grow() {
  std::vector<std::uint64_t> bigger(table_.size() * 2, 0);
  const std::uint64_t mask = bigger.size() - 1;
  for (std::uint64_t slot : table_) {
    if (slot == 0)
      continue;
    const StateId id = static_cast<StateId>((slot & 0xffffffffu) - 1);
    std::uint64_t at = hash_state(state(id), words_) & mask;
    while (bigger[at] != 0)
      at = (at + 1) & mask;
    bigger[at] = slot;
  }
  table_.swap(bigger);
  mask_ = mask;
}

} // namespace checker
