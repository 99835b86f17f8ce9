#include "checker/expansion.hpp"

namespace checker {

void Worker::clear() {
  states.clear();
  candidates.clear();
  edges.clear();
  stuck.clear();
  edge_count = 0;
  expanded = 0;
  error = nullptr;
}

bool Worker::grow_room(std::size_t successors, std::size_t edge_room, std::size_t stuck_room) {
  if (!allowance.fits(bytes(), states.growth_bytes(successors)))
    return false;
  states.grow(successors);
  return grow_within(candidates, successors) && grow_within(edges, edge_room) &&
         grow_within(stuck, stuck_room);
}

template <class T> bool Worker::grow_within(std::vector<T>& v, std::size_t more) {
  if (!allowance.fits(bytes(), growth_bytes(v, more)))
    return false;
  grow(v, more);
  return true;
}

} // namespace checker
