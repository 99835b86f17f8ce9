#pragma once
// Insertion of one state into the store by one thread, within the state and memory
// limits: how the start states enter an exploration (the workers of a level insert
// concurrently, expansion.hpp). A new state gets the next id and its parent. On the
// fingerprint store the store is asked about the state's fingerprint (its key, see
// store_key()), and a new state goes into the level being built (level_states.hpp). On the
// compressed store it is asked about the state's key in the tree (state_tree.hpp).

#include <cstdint>
#include <optional>
#include <vector>

#include "checker/exploration.hpp"
#include "checker/fingerprint.hpp"
#include "checker/level_states.hpp"
#include "checker/memory_budget.hpp"

namespace checker {

// What the store holds for a state: the state itself, or on the fingerprint store its
// fingerprint (`fingerprint` is where it is kept); and the hash of that key.
struct StoreKey {
  const Word* words;
  std::uint64_t hash;
};
inline StoreKey store_key(const Word* state, std::uint32_t words, bool fingerprints,
                          std::uint64_t& fingerprint_of) {
  if (!fingerprints)
    return {state, hash_state(state, words)};
  fingerprint_of = fingerprint(state, words);
  return {&fingerprint_of, hash_state(&fingerprint_of, 1)};
}

class Insertion {
public:
  enum class Outcome { fresh, known, state_limit, memory_limit };
  struct Result {
    Outcome outcome;
    StateId id = 0; // when fresh or known
  };

  // `max_states` 0 means none. `states`: the fingerprint store's level being built
  // (nullptr: the exact store).
  Insertion(Exploration& ex, MemoryBudget& budget, std::uint64_t max_states,
            LevelStates* states = nullptr)
      : ex_(ex), budget_(budget), max_states_(max_states), states_(states) {}

  // The state, keyed by itself (the exact store).
  Result insert(const Word* state, std::uint64_t hash, StateId parent) {
    return insert(state, StoreKey{state, hash}, parent);
  }
  // The state and its key in the store (store_key(); on the compressed store the key is
  // made here).
  Result insert(const Word* state, StoreKey key, StateId parent) {
    if (ex_.tree) {
      if (!tree_key(state))
        return {Outcome::memory_limit};
      key = {&tree_key_, hash_state(&tree_key_, 1)};
    }
    // At the state limit, a state that is not stored yet ends the run (incomplete); so a
    // space of exactly max_states states still finishes.
    if (max_states_ && ex_.store.size() >= max_states_ && !ex_.store.find(key.words, key.hash))
      return {Outcome::state_limit};
    if (!room())
      return {Outcome::memory_limit};
    const auto [id, fresh] = ex_.store.insert(key.words, key.hash);
    if (!fresh)
      return {Outcome::known, id};
    ex_.parent.push_back(parent);
    if (states_)
      states_->put(id, state, 0);
    return {Outcome::fresh, id};
  }

private:
  // The compressed store's key of `state` into tree_key_, its parts put in the tree (which
  // grows within the budget); false at the memory limit.
  bool tree_key(const Word* state) {
    scratch_.resize(ex_.tree->scratch_size());
    for (;;) {
      if (const std::optional<Word> key = ex_.tree->insert(state, scratch_.data())) {
        tree_key_ = *key;
        return true;
      }
      if (!budget_.fits(ex_.tree->room_bytes()))
        return false;
      ex_.tree->make_room();
    }
  }
  // Room for one more state in the store, its parent and (fingerprint store) its state.
  bool room() {
    const std::uint64_t end = ex_.store.size() + 1;
    if (states_ && !budget_.fits(states_->reserve_bytes(end) + states_->growth_bytes(0, 1)))
      return false;
    if (states_) {
      states_->reserve(end);
      states_->make_room(0, 1);
    }
    return budget_.fits(ex_.store.growth_bytes()) && budget_.grow_within(ex_.parent, 1);
  }

  Exploration& ex_;
  MemoryBudget& budget_;
  std::uint64_t max_states_;
  LevelStates* states_;
  Word tree_key_ = 0;
  std::vector<std::uint32_t> scratch_;
};

} // namespace checker
