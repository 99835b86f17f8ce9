#include "checker/discovery.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "checker/parallel_for.hpp"

namespace checker {

namespace {

// order() sorts by bucket of this many consecutive parents first, then each bucket by
// parent with a count per parent small enough to stay in the cache.
constexpr std::uint64_t bucket_parents = 4096;
// The ids a thread counts and places at least (fewer threads below that).
constexpr std::uint64_t ids_per_thread = std::uint64_t{1} << 16;

} // namespace

std::span<const StateId> Discovery::order(std::uint64_t count, StateId parents_begin,
                                          StateId parents_end, std::uint32_t threads,
                                          StateId* parents) {
  // A bucket sort. The ids are cut into one range per thread; each thread counts its
  // range's states per bucket of parents, then places them in `staged_` (by bucket, and
  // in a bucket by range); each bucket then goes into `order_` by a counting sort by
  // parent, and each parent's group by step. Every thread reads only its share of the
  // keys, and no two threads write one entry.
  const std::uint64_t buckets =
      (std::uint64_t{parents_end} - parents_begin + bucket_parents - 1) / bucket_parents;
  const std::uint64_t ranges = std::clamp<std::uint64_t>(count / ids_per_thread, 1, threads);
  auto range_begin = [&](std::uint64_t r) { return count * r / ranges; };
  auto parent_at = [&](std::uint64_t t) { return parent_of(keys_[t]) - parents_begin; };
  auto each = [&](std::uint64_t n, auto&& body) {
    parallel_for(
        static_cast<std::uint32_t>(ranges), n,
        [&](std::uint64_t begin, std::uint64_t end) {
          for (std::uint64_t i = begin; i < end; ++i)
            body(i);
        },
        1);
  };
  // place[r * buckets + b]: how many states range r has in bucket b, then where the next
  // one goes.
  std::vector<std::uint64_t> place(ranges * buckets, 0);
  each(ranges, [&](std::uint64_t r) {
    std::uint64_t* counts = place.data() + r * buckets;
    for (std::uint64_t t = range_begin(r), end = range_begin(r + 1); t < end; ++t)
      if (keys_[t] != hole)
        ++counts[parent_at(t) / bucket_parents];
  });
  std::vector<std::uint64_t> bucket_start(buckets + 1);
  std::uint64_t states = 0;
  for (std::uint64_t b = 0; b < buckets; ++b) {
    bucket_start[b] = states;
    for (std::uint64_t r = 0; r < ranges; ++r)
      states += std::exchange(place[r * buckets + b], states);
  }
  bucket_start[buckets] = states;
  // (The buffers grow without a copy and keep the pages they have: mapped_memory.hpp.)
  order_.reserve(count);
  staged_.reserve(count);
  each(ranges, [&](std::uint64_t r) {
    std::uint64_t* next = place.data() + r * buckets;
    for (std::uint64_t t = range_begin(r), end = range_begin(r + 1); t < end; ++t)
      if (keys_[t] != hole)
        staged_[next[parent_at(t) / bucket_parents]++] = static_cast<StateId>(first_ + t);
  });
  // Each thread takes the buckets that start in its share of the states.
  std::vector<std::uint32_t> group_ends(ranges * (bucket_parents + 1));
  each(ranges, [&](std::uint64_t r) {
    std::uint32_t* ends = group_ends.data() + r * (bucket_parents + 1);
    const auto first_bucket = static_cast<std::uint64_t>(
        std::lower_bound(bucket_start.begin(), bucket_start.end() - 1, states * r / ranges) -
        bucket_start.begin());
    const std::uint64_t share_end = r + 1 == ranges ? states + 1 : states * (r + 1) / ranges;
    for (std::uint64_t b = first_bucket; b < buckets && bucket_start[b] < share_end; ++b) {
      const std::uint64_t begin = bucket_start[b], end = bucket_start[b + 1];
      if (begin == end)
        continue;
      const std::uint64_t low = b * bucket_parents;
      // ends[p + 1]: the states of the bucket's parents up to low + p, then where the
      // group of parent low + p ends.
      std::fill(ends, ends + bucket_parents + 1, 0);
      for (std::uint64_t i = begin; i < end; ++i)
        ++ends[parent_of(key_of(staged_[i])) - parents_begin - low + 1];
      for (std::uint64_t p = 1; p <= bucket_parents; ++p)
        ends[p] += ends[p - 1];
      for (std::uint64_t i = begin; i < end; ++i) {
        const StateId id = staged_[i];
        const StateId parent = parent_of(key_of(id));
        const std::uint64_t at = begin + ends[parent - parents_begin - low]++;
        order_[at] = id;
        if (parents)
          parents[at] = parent;
      }
      // Each parent's group (a few states) by step (the parents stay where they are).
      std::uint64_t group = begin;
      for (std::uint64_t p = 0; p < bucket_parents && group < end; ++p) {
        const std::uint64_t group_end = begin + ends[p];
        for (std::uint64_t i = group + 1; i < group_end; ++i)
          for (std::uint64_t j = i; j > group && key_of(order_[j]) < key_of(order_[j - 1]); --j)
            std::swap(order_[j], order_[j - 1]);
        group = group_end;
      }
    }
  });
  return {order_.data(), states};
}

std::span<const StateId> Discovery::dense_order(std::uint64_t count, StateId* parents) {
  std::uint64_t states = 0;
  for (std::uint64_t t = 0; t < count; ++t)
    states += keys_[t] != hole;
  order_.reserve(states);
  // The holes below `states` are as many as the states from `states` on.
  std::uint64_t back = count;
  for (std::uint64_t t = 0; t < states; ++t) {
    if (keys_[t] != hole) {
      order_[t] = static_cast<StateId>(first_ + t);
      continue;
    }
    do
      --back;
    while (keys_[back] == hole);
    order_[t] = static_cast<StateId>(first_ + back);
  }
  if (parents)
    for (std::uint64_t i = 0; i < states; ++i)
      parents[i] = parent_of(key_of(order_[i]));
  return {order_.data(), states};
}

std::span<const StateId> Discovery::new_ids(std::span<const StateId> order, std::uint64_t count,
                                            std::uint32_t threads) {
  staged_.reserve(count);
  parallel_for(threads, order.size(), [&](std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t i = begin; i < end; ++i)
      staged_[order[i] - first_] = static_cast<StateId>(first_ + i);
  });
  return {staged_.data(), count};
}

} // namespace checker
