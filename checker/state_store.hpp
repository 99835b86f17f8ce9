#pragma once
// The visited-state store. Each state is held once, in the arena, in id order (ids are
// dense), so per-state data lives in arrays indexed by id and expanding a level reads the
// arena sequentially. The hash table holds 32-bit slots:
//
//   slot = tag << m | (id + 1)      with 2^m slots; 0 is an empty slot
//
// The id takes the low m bits (the table is at most three quarters full, so id + 1 <
// 2^m - 1; the all-ones id marks a slot being filled), and the 32 - m bits left keep a tag
// of the hash, so that a lookup reads the arena only when the tags agree. The home slot
// is the hash's low m bits; the tag comes from its high bits. At 2^24 slots (up to 12.5
// million states) a slot costs 5.3 to 10.7 bytes per state, with 8 tag bits.
//
// Threads insert concurrently (find_or_insert): a new state claims an empty slot with a
// compare-and-swap, takes the next id, is copied into the arena and is then published
// with its id; a lookup that meets a slot being filled with its tag waits for it. The
// store never grows on its own there: find_or_insert says `full` when it has no room, and
// make_room() is then called while no thread uses the store (growth_gate.hpp).
//
// Growth never holds two tables: the old one is given back first and the new one, twice
// as big, is filled again from the arena. The arena is mapped memory that grows without a
// copy (mapped_memory.hpp), but it may move.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
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
  std::uint64_t size() const { return counter().load(std::memory_order_relaxed); }
  const Word* state(StateId id) const { return arena_.data() + std::size_t{id} * words_; }

  // Starts loading the slot where a state with this hash would be.
  void prefetch(std::uint64_t hash) const { __builtin_prefetch(table_.data() + (hash & mask_)); }
  // Starts loading the state a lookup of this hash compares first: the one its home slot
  // holds, when the tags agree. A hint only (the slot may change before the lookup);
  // while the table cannot grow (between two checkpoints of the growth gate).
  void prefetch_state(std::uint64_t hash) const {
    const std::uint64_t slot =
        std::atomic_ref<std::uint32_t>(const_cast<std::uint32_t&>(table_[hash & mask_]))
            .load(std::memory_order_relaxed);
    if (slot != 0 && (slot >> bits_) == tag_of(hash) && (slot & mask_) != mask_)
      __builtin_prefetch(state(static_cast<StateId>((slot & mask_) - 1)));
  }

  std::optional<StateId> find(const Word* state, std::uint64_t hash) const {
    const std::uint64_t tag = tag_of(hash);
    for (std::uint64_t at = hash & mask_;; at = (at + 1) & mask_) {
      const std::uint64_t slot = published(at);
      if (slot == 0)
        return std::nullopt;
      if ((slot >> bits_) == tag) {
        const StateId id = static_cast<StateId>((slot & mask_) - 1);
        if (same(this->state(id), state))
          return id;
      }
    }
  }

  struct Claim {
    enum class Kind { known, fresh, full } kind;
    StateId id = 0; // when known or fresh
  };

  // The ids a thread hands to new states, taken from the store `size` at a time, so that
  // threads do not write the same cache lines of the arena (and of arrays indexed by id)
  // in turn. The ids of a block left unused are holes, which reorder() removes.
  struct IdBlock {
    std::uint64_t next = 0, end = 0;
    std::uint32_t size = 1;
  };

  // The state's id, inserting it when it is new (with the next id of `ids`); safe with
  // other threads doing the same, each with its own block.
  // `on_fresh(id, slot)` runs for a new state before other threads can find it (`slot`:
  // where the table holds it, until the table grows). `full`: there is
  // no room for one more state (make_room() first).
  template <class OnFresh>
  Claim find_or_insert(const Word* state, std::uint64_t hash, IdBlock& ids, OnFresh&& on_fresh) {
    const std::uint64_t tag = tag_of(hash);
    for (std::uint64_t at = hash & mask_;; at = (at + 1) & mask_) {
      std::uint32_t slot =
          std::atomic_ref<std::uint32_t>(table_[at]).load(std::memory_order_acquire);
      if (slot == 0) {
        if (ids.next == ids.end && counter().load(std::memory_order_relaxed) >= room_)
          return {Claim::Kind::full};
        const auto filling = static_cast<std::uint32_t>((tag << bits_) | mask_);
        if (std::atomic_ref<std::uint32_t>(table_[at])
                .compare_exchange_strong(slot, filling, std::memory_order_acquire)) {
          if (ids.next == ids.end) {
            ids.next = counter().fetch_add(ids.size, std::memory_order_relaxed);
            ids.end = ids.next + ids.size;
          }
          const auto id = static_cast<StateId>(ids.next++);
          Word* to = arena_.data() + std::size_t{id} * words_;
          for (std::uint32_t i = 0; i < words_; ++i)
            to[i] = state[i];
          on_fresh(id, static_cast<std::uint32_t>(at));
          std::atomic_ref<std::uint32_t>(table_[at])
              .store(static_cast<std::uint32_t>((tag << bits_) | (std::uint64_t{id} + 1)),
                     std::memory_order_release);
          return {Claim::Kind::fresh, id};
        }
        // Another thread took the slot first: look at what it put there.
      }
      if ((slot >> bits_) != tag)
        continue;
      while ((slot & mask_) == mask_) // being filled
        slot = std::atomic_ref<std::uint32_t>(table_[at]).load(std::memory_order_acquire);
      const StateId id = static_cast<StateId>((slot & mask_) - 1);
      if (same(this->state(id), state))
        return {Claim::Kind::known, id};
    }
  }

  // For one thread at a time: the id of the state, and whether it was new.
  std::pair<StateId, bool> insert(const Word* state, std::uint64_t hash);

  // The room find_or_insert leaves for the threads that may pass its check at once (a
  // block each): at least as many threads as insert concurrently, and their block size.
  // As many threads refill the table when it grows and renumber a level.
  void set_inserters(std::uint32_t inserters, std::uint32_t block = 1);
  // Room for `more` states beyond size() (and for the inserters' slack): a bigger table,
  // a longer arena. While no thread uses the store. The bytes it would add first:
  std::size_t room_bytes(std::uint64_t more) const;
  // `holds(id)` says which ids below size() hold a state when some do not (the unused
  // ids of blocks handed out during a level): only those go into a new table.
  // `placed(id, slot)`, when given, hears where a new table puts each id (so that a
  // level's renumbering need not look its states up again).
  void make_room(std::uint64_t more, const std::function<bool(StateId)>& holds = {},
                 const std::function<void(StateId, std::uint32_t)>& placed = {});

  // find_or_insert inserts while size() is below this (then it says `full`).
  std::uint64_t room() const { return room_; }
  // Every id find_or_insert may hand out before it says `full` is below this.
  std::uint64_t id_limit() const { return room_ + slack_; }

  // How many times the table was built (slots move then).
  std::uint64_t tables_built() const { return tables_built_; }

  // Keeps the first `n` states (the rest are forgotten); while no thread uses the store.
  void truncate(std::uint64_t n);
  // Renumbers the states from `first` on: the state `order[i]` gets the id first + i
  // (`order` holds every id from first on that is not a hole, in any order; the holes
  // go). `slots[t]` is where the table holds the state first + t (nullptr: found here). While no
  // thread uses the store. `in_place`: the states move along the permutation's cycles,
  // one at a time, instead of through a copy of the level (reorder_copy_bytes()): slower,
  // for when that copy does not fit in the memory limit.
  // `scratch`: where the copy of the level goes when it holds reorder_copy_bytes() (else
  // a buffer of its own is allocated, or with `in_place` none); with it, never in place.
  void reorder(StateId first, std::span<const StateId> order, const std::uint32_t* slots,
               bool in_place = false, std::span<Word> scratch = {});
  // reorder() for an order that moves few states (Discovery::dense_order): only the states
  // that move are touched.
  void fill_holes(StateId first, std::span<const StateId> order, const std::uint32_t* slots);
  // What reorder() allocates for the copy of the level's states from `first` on (in place:
  // a bit per state and a word per hole, which are few).
  std::size_t reorder_copy_bytes(StateId first) const {
    return (size() - first) * words_ * sizeof(Word);
  }
  // Where the table holds the state `id` (stored); while nobody inserts.
  std::uint32_t slot_of(StateId id) const;

  // What the store counts as held: the table and the arena (in steps, see MappedVector).
  std::size_t memory_bytes() const { return table_.bytes() + arena_bytes_; }

  // The bytes memory_bytes() grows by at the next insert() (0 when it does not grow). The
  // table's old buffer is given back before the new one is taken.
  std::size_t growth_bytes() const { return size() < room_ ? 0 : room_bytes(1); }

  // Three quarters of the largest table (2^32 slots).
  static constexpr std::uint64_t max_states = 0xc0000000u;

private:
  // reorder() in place: position i takes the state at order[i] - first (holes after).
  void permute_in_place(Word* level, std::size_t count, std::span<const StateId> order,
                        StateId first);
  bool same(const Word* a, const Word* b) const {
    for (std::uint32_t i = 0; i < words_; ++i)
      if (a[i] != b[i])
        return false;
    return true;
  }
  std::uint32_t published(std::uint64_t at) const {
    std::uint32_t slot;
    do
      slot = std::atomic_ref<std::uint32_t>(const_cast<std::uint32_t&>(table_[at]))
                 .load(std::memory_order_acquire);
    while ((slot & mask_) == mask_); // being filled
    return slot;
  }
  std::atomic_ref<std::uint64_t> counter() const {
    return std::atomic_ref<std::uint64_t>(const_cast<std::uint64_t&>(count_));
  }
  std::uint64_t tag_of(std::uint64_t hash) const { return bits_ < 32 ? hash >> (32 + bits_) : 0; }
  // The states a table of 2^bits slots holds at most.
  static std::uint64_t table_states(std::uint32_t bits) { return (std::uint64_t{3} << bits) / 4; }
  // The table bits and arena capacity (in states) for `states` states and the slack.
  std::uint32_t bits_for(std::uint64_t states) const;
  std::uint64_t arena_states_for(std::uint64_t states) const;
  // The table with 2^bits slots, filled from the arena (the ids `holds`, all when empty;
  // `placed` as in make_room()).
  void rebuild(std::uint32_t bits, const std::function<bool(StateId)>& holds = {},
               const std::function<void(StateId, std::uint32_t)>& placed = {});
  void update_room();
  std::uint64_t hash_of(std::uint64_t id) const {
    return hash_state(state(static_cast<StateId>(id)), words_);
  }
  // Puts the states of ids [begin, end) (those `holds`, all when empty) in the table;
  // `concurrent`: other threads fill other ranges at once.
  void fill(std::uint64_t begin, std::uint64_t end, const std::function<bool(StateId)>& holds,
            const std::function<void(StateId, std::uint32_t)>& placed, bool concurrent);
  // Puts `id` in the table (no lookup uses it meanwhile); the slot it took.
  std::uint32_t place(StateId id, std::uint64_t hash, bool concurrent);

  std::uint32_t words_;
  std::uint32_t bits_ = 0; // m: 2^m slots
  std::uint64_t mask_ = 0; // 2^m - 1
  // Written by every insertion: on a cache line of its own, away from what every lookup
  // reads. Read and written through counter().
  alignas(64) std::uint64_t count_ = 0;
  char count_line_[64 - sizeof(std::uint64_t)];
  std::uint64_t room_ = 0; // find_or_insert inserts while size() < room_
  std::uint64_t tables_built_ = 0;
  std::uint64_t slack_ = 1;        // inserters
  std::uint32_t threads_ = 1;      // that refill the table and renumber a level together
  std::uint64_t arena_states_ = 0; // capacity counted as held, in states
  std::size_t arena_bytes_ = 0;    // = arena_states_ * words * 8
  MappedArray<Word> arena_;
  MappedArray<std::uint32_t> table_;
};

} // namespace checker
