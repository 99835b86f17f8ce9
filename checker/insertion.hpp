#pragma once
// Insertion of one state into the store, within the state and memory limits: the one
// way states enter an exploration, used for the start states and by the merge. A new
// state gets the next id, its parent and a place in the level being built.

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

  // `max_states` 0 means none; with `record_edges`, room for one edge is made as well.
  Insertion(Exploration& ex, MemoryBudget& budget, std::uint64_t max_states, bool record_edges)
      : ex_(ex), budget_(budget), max_states_(max_states), record_edges_(record_edges) {}

  bool records_edges() const { return record_edges_; }

  Result insert(const Word* state, std::uint64_t hash, StateId parent,
                std::vector<StateId>& level) {
    // At the state limit, a state that is not stored yet ends the run (incomplete); so a
    // space of exactly max_states states still finishes.
    if (max_states_ && ex_.store.size() >= max_states_ && !ex_.store.find(state, hash))
      return {Outcome::state_limit};
    if (!room(level))
      return {Outcome::memory_limit};
    const auto [id, fresh] = ex_.store.insert(state, hash);
    if (!fresh)
      return {Outcome::known, id};
    ex_.parent.push_back(parent);
    level.push_back(id);
    return {Outcome::fresh, id};
  }

private:
  // Room for one more state in the store, its parent, its place in `level` and its edge.
  bool room(std::vector<StateId>& level) {
    return budget_.fits(ex_.store.growth_bytes()) && budget_.grow_within(ex_.parent, 1) &&
           budget_.grow_within(level, 1) &&
           (!record_edges_ || budget_.grow_within(ex_.edge_list, 1));
  }

  Exploration& ex_;
  MemoryBudget& budget_;
  std::uint64_t max_states_;
  bool record_edges_;
};

} // namespace checker
