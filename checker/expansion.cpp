#include "checker/expansion.hpp"

namespace checker {

void Worker::clear() {
  known_edges.clear();
  new_edges.clear();
  stuck.clear();
  targets.clear();
  edge_count = 0;
  expanded = 0;
  inserted = 0;
  error = nullptr;
}

template <class T> bool Worker::grow_within(std::vector<T>& v, std::size_t more) {
  if (!allowance.fits(bytes(), growth_bytes(v, more)))
    return false;
  grow(v, more);
  return true;
}

bool Worker::grow_room(std::size_t edge_room, std::size_t stuck_room) {
  return grow_within(known_edges, edge_room) && grow_within(new_edges, edge_room) &&
         grow_within(stuck, stuck_room);
}

} // namespace checker
