#include "checker/discovery.hpp"

#include <algorithm>

#include "checker/parallel_for.hpp"

namespace checker {

UninitialisedVector<StateId> Discovery::order(std::uint64_t count, StateId parents_begin,
                                              StateId parents_end, std::uint32_t threads) const {
  // A counting sort by parent, then each parent's group by step. With several threads,
  // each takes a range of parents: it reads every key and counts and places those of its
  // parents, so no two threads write one entry and the order is the same for any number.
  const std::uint64_t parents = std::uint64_t{parents_end} - parents_begin;
  UninitialisedVector<StateId> start(parents + 1); // (zeroed by the threads, a range each)
  start[0] = 0;
  auto each_range = [&](auto&& body) { parallel_for(threads, parents, body, 1 << 14); };
  each_range([&](std::uint64_t begin, std::uint64_t end) {
    std::fill(start.begin() + static_cast<std::ptrdiff_t>(begin + 1),
              start.begin() + static_cast<std::ptrdiff_t>(end + 1), 0);
    for (std::uint64_t t = 0; t < count; ++t)
      if (keys_[t] != hole) {
        const std::uint64_t p = parent_of(keys_[t]) - parents_begin;
        if (p >= begin && p < end)
          ++start[p + 1];
      }
  });
  for (std::size_t p = 1; p < start.size(); ++p)
    start[p] += start[p - 1];
  UninitialisedVector<StateId> order(start.back());
  each_range([&](std::uint64_t begin, std::uint64_t end) {
    const StateId first_place = start[begin]; // (start[p] becomes where p's group ends)
    for (std::uint64_t t = 0; t < count; ++t)
      if (keys_[t] != hole) {
        const std::uint64_t p = parent_of(keys_[t]) - parents_begin;
        if (p >= begin && p < end)
          order[start[p]++] = static_cast<StateId>(first_ + t);
      }
    auto by_key = [&](StateId a, StateId b) { return key_of(a) < key_of(b); };
    StateId group = first_place;
    for (std::uint64_t p = begin; p < end; ++p) {
      if (start[p] - group > 1)
        std::sort(order.begin() + group, order.begin() + start[p], by_key);
      group = start[p];
    }
  });
  return order;
}

UninitialisedVector<StateId> Discovery::dense_order(std::uint64_t count) const {
  std::uint64_t states = 0;
  for (std::uint64_t t = 0; t < count; ++t)
    states += keys_[t] != hole;
  // The holes below `states` are as many as the states from `states` on.
  UninitialisedVector<StateId> order(states);
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
