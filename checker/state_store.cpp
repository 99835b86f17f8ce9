#include "checker/state_store.hpp"

#include "checker/parallel_for.hpp"

#include <memory>
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
  threads_ = std::max<std::uint32_t>(inserters, 1);
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

void StateStore::make_room(std::uint64_t more, const std::function<bool(StateId)>& holds,
                           const std::function<void(StateId, std::uint32_t)>& placed) {
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
    rebuild(bits, holds, placed);
  update_room();
}

void StateStore::update_room() {
  const std::uint64_t fits = std::min(table_states(bits_), arena_states_);
  room_ = fits > slack_ ? fits - slack_ : 0;
}

void StateStore::rebuild(std::uint32_t bits, const std::function<bool(StateId)>& holds,
                         const std::function<void(StateId, std::uint32_t)>& placed) {
  ++tables_built_;
  table_.release();
  bits_ = bits;
  mask_ = (std::uint64_t{1} << bits) - 1;
  table_ = MappedArray<std::uint32_t>(mask_ + 1);
  const bool concurrent = threads_ > 1;
  parallel_for(threads_, size(), [&](std::uint64_t begin, std::uint64_t end) {
    fill(begin, end, holds, placed, concurrent);
  });
}

void StateStore::fill(std::uint64_t begin, std::uint64_t end,
                      const std::function<bool(StateId)>& holds,
                      const std::function<void(StateId, std::uint32_t)>& placed, bool concurrent) {
  // A ring of the next states to place, their slots prefetched.
  std::uint64_t ids[rebuild_prefetch], hashes[rebuild_prefetch];
  std::uint64_t head = 0, queued = 0, next = begin;
  for (;;) {
    while (queued < rebuild_prefetch && next < end) {
      const std::uint64_t id = next++;
      if (holds && !holds(static_cast<StateId>(id)))
        continue;
      const std::uint64_t at = (head + queued++) % rebuild_prefetch;
      ids[at] = id;
      prefetch(hashes[at] = hash_of(id));
    }
    if (queued == 0)
      return;
    const auto id = static_cast<StateId>(ids[head]);
    const std::uint32_t slot = place(id, hashes[head], concurrent);
    if (placed)
      placed(id, slot);
    head = (head + 1) % rebuild_prefetch;
    --queued;
  }
}

std::uint32_t StateStore::place(StateId id, std::uint64_t hash, bool concurrent) {
  const auto value = static_cast<std::uint32_t>((tag_of(hash) << bits_) | (std::uint64_t{id} + 1));
  for (std::uint64_t at = hash & mask_;; at = (at + 1) & mask_) {
    if (!concurrent) {
      if (table_[at] == 0) {
        table_[at] = value;
        return static_cast<std::uint32_t>(at);
      }
      continue;
    }
    std::uint32_t empty = 0;
    if (std::atomic_ref<std::uint32_t>(table_[at])
            .compare_exchange_strong(empty, value, std::memory_order_relaxed))
      return static_cast<std::uint32_t>(at);
  }
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

void StateStore::reorder(StateId first, std::span<const StateId> order, const std::uint32_t* slots,
                         bool in_place, std::span<Word> scratch) {
  const std::size_t n = order.size();
  std::vector<std::uint32_t> found;
  if (!slots) {
    found.resize(size() - first);
    parallel_for(threads_, n, [&](std::uint64_t begin, std::uint64_t end) {
      for (std::uint64_t i = begin; i < end; ++i)
        found[order[i] - first] = slot_of(order[i]);
    });
    slots = found.data();
  }
  const auto id_bits = static_cast<std::uint32_t>(mask_);
  Word* level = arena_.data() + std::size_t{first} * words_;
  parallel_for(threads_, n, [&](std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t i = begin; i < end; ++i) {
      if (i + 8 < end)
        __builtin_prefetch(table_.data() + slots[order[i + 8] - first]);
      std::uint32_t& slot = table_[slots[order[i] - first]];
      slot = (slot & ~id_bits) | static_cast<std::uint32_t>(first + i + 1);
    }
  });
  const std::size_t count = size() - first;            // holes included
  const bool spare = scratch.size() >= count * words_; // (then the copy costs nothing)
  if (in_place && !spare)
    permute_in_place(level, count, order, first);
  else {
    std::unique_ptr<Word[]> own; // (not zeroed: copied over)
    if (!spare)
      own.reset(new Word[count * words_]);
    Word* before = spare ? scratch.data() : own.get();
    parallel_for(threads_, count * words_, [&](std::uint64_t begin, std::uint64_t end) {
      std::copy(level + begin, level + end, before + begin);
    });
    parallel_for(threads_, n, [&](std::uint64_t begin, std::uint64_t end) {
      for (std::uint64_t i = begin; i < end; ++i)
        std::copy_n(before + std::size_t{order[i] - first} * words_, words_, level + i * words_);
    });
  }
  count_ = first + n;
}

void StateStore::fill_holes(StateId first, std::span<const StateId> order,
                            const std::uint32_t* slots) {
  const auto id_bits = static_cast<std::uint32_t>(mask_);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const StateId from = order[i], to = static_cast<StateId>(first + i);
    if (from == to)
      continue;
    std::uint32_t& slot = table_[slots ? slots[from - first] : slot_of(from)];
    slot = (slot & ~id_bits) | (to + 1);
    std::copy_n(state(from), words_, arena_.data() + std::size_t{to} * words_);
  }
  count_ = first + order.size();
}

void StateStore::permute_in_place(Word* level, std::size_t count, std::span<const StateId> order,
                                  StateId first) {
  // The position i < n takes the state at order[i] - first; the positions of the holes
  // take the places from n on, in increasing order, so that the whole is a permutation of
  // [0, count) whose cycles can be followed with one state held aside.
  const std::size_t n = order.size();
  std::vector<bool> is_state(count, false);
  for (std::size_t i = 0; i < n; ++i)
    is_state[order[i] - first] = true;
  std::vector<std::size_t> hole_source; // of the positions n, n + 1, ...
  hole_source.reserve(count - n);
  for (std::size_t p = 0; p < count; ++p)
    if (!is_state[p])
      hole_source.push_back(p);
  auto from = [&](std::size_t i) {
    return i < n ? std::size_t{order[i] - first} : hole_source[i - n];
  };
  std::vector<bool>& placed = is_state; // (reused: every entry is set again below)
  placed.assign(count, false);
  std::vector<Word> held(words_);
  for (std::size_t start = 0; start < count; ++start) {
    if (placed[start])
      continue;
    std::copy_n(level + start * words_, words_, held.begin());
    std::size_t i = start;
    for (;;) {
      placed[i] = true;
      const std::size_t src = from(i);
      if (src == start) {
        std::copy_n(held.begin(), words_, level + i * words_);
        break;
      }
      std::copy_n(level + src * words_, words_, level + i * words_);
      i = src;
    }
  }
}

} // namespace checker
