#pragma once
// The frontier of a level-synchronous breadth-first search: the ids of the level being
// expanded (current) and of the level being built from it (next). Level 0, the start
// states, is built as `next` too. Both keep their memory from level to level.

#include <cstddef>
#include <span>
#include <vector>

#include "checker/state_store.hpp"

namespace checker {

class Frontier {
public:
  std::span<const StateId> current() const { return current_; }
  // The level being built; ids are appended in the order they are to be expanded.
  std::vector<StateId>& next() { return next_; }
  const std::vector<StateId>& next() const { return next_; }

  // The level built becomes the one to expand; the next one starts empty.
  void advance() {
    current_.swap(next_);
    next_.clear();
  }
  bool empty() const { return current_.empty(); }
  std::size_t bytes() const { return (current_.capacity() + next_.capacity()) * sizeof(StateId); }

private:
  std::vector<StateId> current_, next_;
};

} // namespace checker
