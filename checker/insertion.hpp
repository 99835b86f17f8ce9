#pragma once
// Insertion of one state into the store by one thread, within the state and memory
// limits: how the start states enter an exploration (the workers of a level insert
// concurrently, expansion.hpp). A new state gets the next id and its parent.

#include <cstdint>
#include <vector>

#include "checker/exploration.hpp"
#include "checker/memory_budget.hpp"

namespace checker {

class Insertion {
public:
  enum class Outcome { fresh, known, state_limit, memory_limit };
  struct Result {
    Outcome outcome;
    StateId id = 0; // when fresh or known
  };

  // `max_states` 0 means none.
  Insertion(Exploration& ex, MemoryBudget& budget, std::uint64_t max_states)
      : ex_(ex), budget_(budget), max_states_(max_states) {}

  Result insert(const Word* state, std::uint64_t hash, StateId parent) {
    // At the state limit, a state that is not stored yet ends the run (incomplete); so a
    // space of exactly max_states states still finishes.
    if (max_states_ && ex_.store.size() >= max_states_ && !ex_.store.find(state, hash))
      return {Outcome::state_limit};
    if (!room())
      return {Outcome::memory_limit};
    const auto [id, fresh] = ex_.store.insert(state, hash);
    if (!fresh)
      return {Outcome::known, id};
    ex_.parent.push_back(parent);
    return {Outcome::fresh, id};
  }

private:
  // Room for one more state in the store and its parent.
  bool room() {
    return budget_.fits(ex_.store.growth_bytes()) && budget_.grow_within(ex_.parent, 1);
  }

  Exploration& ex_;
  MemoryBudget& budget_;
  std::uint64_t max_states_;
};

} // namespace checker
