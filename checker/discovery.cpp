#include "checker/discovery.hpp"

#include <algorithm>

namespace checker {

std::vector<StateId> Discovery::order(std::uint64_t count, StateId parents_begin,
                                      StateId parents_end) const {
  std::vector<StateId> start(std::size_t{parents_end - parents_begin} + 1, 0);
  std::uint64_t states = 0;
  for (std::uint64_t t = 0; t < count; ++t)
    if (keys_[t] != hole) {
      ++start[parent_of(keys_[t]) - parents_begin + 1];
      ++states;
    }
  for (std::size_t p = 1; p < start.size(); ++p)
    start[p] += start[p - 1];
  std::vector<StateId> order(states);
  for (std::uint64_t t = 0; t < count; ++t)
    if (keys_[t] != hole)
      order[start[parent_of(keys_[t]) - parents_begin]++] = static_cast<StateId>(first_ + t);
  // Each parent's states, now together, by step (start[p] is where p's group ends).
  auto by_key = [&](StateId a, StateId b) { return key_of(a) < key_of(b); };
  StateId group = 0;
  for (std::size_t p = 0; p + 1 < start.size(); ++p) {
    if (start[p] - group > 1)
      std::sort(order.begin() + group, order.begin() + start[p], by_key);
    group = start[p];
  }
  return order;
}

std::vector<StateId> Discovery::dense_order(std::uint64_t count) const {
  std::uint64_t states = 0;
  for (std::uint64_t t = 0; t < count; ++t)
    states += keys_[t] != hole;
  // The holes below `states` are as many as the states from `states` on.
  std::vector<StateId> order(states);
  std::uint64_t back = count;
  for (std::uint64_t t = 0; t < states; ++t) {
    if (keys_[t] != hole) {
      order[t] = static_cast<StateId>(first_ + t);
      continue;
    }
    do
      --back;
    while (keys_[back] == hole);
    order[t] = static_cast<StateId>(first_ + back);
  }
  return order;
}

} // namespace checker
