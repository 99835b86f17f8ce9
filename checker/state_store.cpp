#include "checker/state_store.hpp"

#include <stdexcept>
#include <vector>

namespace checker {

namespace {
constexpr std::uint32_t initial_bits = 10;
// States hashed ahead of the one placed while the table is filled again.
constexpr std::uint64_t rebuild_prefetch = 16;
// The arena grows by an eighth, and by at least this many states.
constexpr std::uint64_t arena_step = 512;
} // namespace

StateStore::StateStore(std::uint32_t words) : words_(words) {
  rebuild(initial_bits);
  update_room();
}

std::pair<StateId, bool> StateStore::insert(const Word* state, std::uint64_t hash) {
  for (;;) {
    IdBlock one;
    const Claim claim = find_or_insert(state, hash, one, [](StateId, std::uint32_t) {});
    if (claim.kind != Claim::Kind::full)
      return {claim.id, claim.kind == Claim::Kind::fresh};
    make_room(1);
  }
}

void StateStore::set_inserters(std::uint32_t inserters, std::uint32_t block) {
  slack_ = std::uint64_t{std::max<std::uint32_t>(inserters, 1)} * std::max<std::uint32_t>(block, 1);
  update_room();
}

std::uint32_t StateStore::bits_for(std::uint64_t states) const {
  std::uint32_t bits = bits_;
  while (table_states(bits) < states)
    ++bits;
  return bits;
}

std::uint64_t StateStore::arena_states_for(std::uint64_t states) const {
  if (states <= arena_states_)
    return arena_states_;
  return std::max({states, arena_states_ + arena_states_ / 8, arena_step});
}

std::size_t StateStore::room_bytes(std::uint64_t more) const {
  const std::uint64_t needed = size() + more + slack_;
  const std::uint32_t bits = bits_for(needed);
  std::size_t bytes =
      ((std::size_t{1} << bits) - (std::size_t{1} << bits_)) * sizeof(std::uint32_t);
  bytes += (arena_states_for(needed) - arena_states_) * words_ * sizeof(Word);
  return bytes;
}

void StateStore::make_room(std::uint64_t more, const std::function<bool(StateId)>& holds) {
  const std::uint64_t needed = size() + more + slack_;
  if (needed > max_states + slack_)
    throw std::length_error("state store is full (3 * 2^30 states)");
  const std::uint64_t arena_states = arena_states_for(needed);
  if (arena_states > arena_states_) {
    arena_.reserve(arena_states * words_);
    arena_states_ = arena_states;
    arena_bytes_ = arena_states * words_ * sizeof(Word);
  }
  if (const std::uint32_t bits = bits_for(needed); bits > bits_)
    rebuild(bits, holds);
  update_room();
}

void StateStore::update_room() {
  const std::uint64_t fits = std::min(table_states(bits_), arena_states_);
  room_ = fits > slack_ ? fits - slack_ : 0;
}

void StateStore::rebuild(std::uint32_t bits, const std::function<bool(StateId)>& holds) {
  ++tables_built_;
  table_.release();
  bits_ = bits;
  mask_ = (std::uint64_t{1} << bits) - 1;
  table_ = MappedArray<std::uint32_t>(mask_ + 1);
  const std::uint64_t count = size();
  if (holds) { // some ids are holes: no prefetching ahead, it is rare
    for (std::uint64_t id = 0; id < count; ++id)
      if (holds(static_cast<StateId>(id)))
        place(static_cast<StateId>(id), hash_of(id));
    return;
  }
  std::uint64_t ahead[rebuild_prefetch];
  for (std::uint64_t id = 0; id < std::min(count, rebuild_prefetch); ++id)
    prefetch(ahead[id] = hash_of(id));
  for (std::uint64_t id = 0; id < count; ++id) {
    const std::uint64_t hash = ahead[id % rebuild_prefetch];
    if (id + rebuild_prefetch < count)
      prefetch(ahead[id % rebuild_prefetch] = hash_of(id + rebuild_prefetch));
    place(static_cast<StateId>(id), hash);
  }
}

void StateStore::place(StateId id, std::uint64_t hash) {
  std::uint64_t at = hash & mask_;
  while (table_[at] != 0)
    at = (at + 1) & mask_;
  table_[at] = static_cast<std::uint32_t>((tag_of(hash) << bits_) | (std::uint64_t{id} + 1));
}

void StateStore::truncate(std::uint64_t n) {
  if (n >= size())
    return;
  count_ = n;
  rebuild(bits_);
}

std::uint32_t StateStore::slot_of(StateId id) const {
  std::uint64_t at = hash_state(state(id), words_) & mask_;
  while ((table_[at] & mask_) != std::uint64_t{id} + 1)
    at = (at + 1) & mask_;
  return static_cast<std::uint32_t>(at);
}

void StateStore::reorder(StateId first, std::span<const StateId> order,
                         const std::uint32_t* slots) {
  const std::size_t n = order.size();
  std::vector<std::uint32_t> found;
  if (!slots) {
    found.resize(size() - first);
    for (StateId id : order)
      found[id - first] = slot_of(id);
    slots = found.data();
  }
  const auto id_bits = static_cast<std::uint32_t>(mask_);
  for (std::size_t i = 0; i < n; ++i) {
    if (i + 8 < n)
      __builtin_prefetch(table_.data() + slots[order[i + 8] - first]);
    std::uint32_t& slot = table_[slots[order[i] - first]];
    slot = (slot & ~id_bits) | static_cast<std::uint32_t>(first + i + 1);
  }
  Word* level = arena_.data() + std::size_t{first} * words_;
  const std::vector<Word> before(level, level + (size() - first) * words_);
  count_ = first + n;
  for (std::size_t i = 0; i < n; ++i)
    std::copy_n(before.data() + std::size_t{order[i] - first} * words_, words_, level + i * words_);
}

} // namespace checker
