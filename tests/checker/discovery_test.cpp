#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "checker/discovery.hpp"

using checker::Discovery;
using checker::StateId;

namespace {

// A level of `count` ids from `first` on, a tenth of them holes, each state found first
// by a step of a parent among [parents_begin, parents_begin + parents); the keys are
// distinct, as the explorer's are.
Discovery random_level(StateId first, std::uint64_t count, StateId parents_begin,
                       std::uint32_t parents, std::uint64_t seed) {
  Discovery discovery;
  discovery.begin(first);
  discovery.make_room(first + count);
  std::mt19937_64 random(seed);
  std::vector<std::uint64_t> keys;
  for (std::uint32_t p = 0; p < parents; ++p)
    for (std::uint64_t step = 0; step < 8; ++step)
      keys.push_back(Discovery::key(parents_begin + p, step));
  std::shuffle(keys.begin(), keys.end(), random);
  for (std::uint64_t t = 0; t < count; ++t) {
    if (random() % 10 == 0)
      discovery.holes(first + t, first + t + 1);
    else
      discovery.found(static_cast<StateId>(first + t), keys[t]);
  }
  return discovery;
}

} // namespace

TEST_CASE("discovery: a level's order is by key, the holes left out, for any number of threads",
          "[checker][discovery]") {
  const StateId first = 1000, parents_begin = 200;
  const std::uint32_t parents = 70000; // more than one thread's share (parallel_for)
  const std::uint64_t count = 300000;
  Discovery discovery = random_level(first, count, parents_begin, parents, 7);

  std::vector<StateId> expected;
  for (std::uint64_t t = 0; t < count; ++t)
    if (discovery.key_of(static_cast<StateId>(first + t)) != Discovery::hole)
      expected.push_back(static_cast<StateId>(first + t));
  std::sort(expected.begin(), expected.end(),
            [&](StateId a, StateId b) { return discovery.key_of(a) < discovery.key_of(b); });
  REQUIRE(expected.size() < count); // some holes

  for (const std::uint32_t threads : {1u, 2u, 3u, 4u}) {
    INFO("threads " << threads);
    const auto order = discovery.order(count, parents_begin, parents_begin + parents, threads);
    CHECK(std::vector<StateId>(order.begin(), order.end()) == expected);
    // The new ids: each state's place in the order, from `first` on.
    const auto new_ids = discovery.new_ids(order, count, threads);
    std::size_t misplaced = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
      misplaced += new_ids[expected[i] - first] != first + i;
    CHECK(misplaced == 0);
  }
}

TEST_CASE("discovery: a level whose states have few parents in many buckets keeps its key order",
          "[checker][discovery]") {
  // Parents far apart (most buckets of parents empty), several states per parent.
  const StateId first = 5000000, parents_begin = 3;
  const std::uint32_t parents = 4000000;
  const std::uint64_t count = 200000;
  Discovery discovery;
  discovery.begin(first);
  discovery.make_room(first + count);
  std::mt19937_64 random(11);
  std::vector<std::uint64_t> keys;
  for (std::uint64_t t = 0; keys.size() < count; ++t)
    keys.push_back(
        Discovery::key(static_cast<StateId>(parents_begin + (t / 5) * 97 % parents), t % 5));
  std::shuffle(keys.begin(), keys.end(), random);
  for (std::uint64_t t = 0; t < count; ++t)
    discovery.found(static_cast<StateId>(first + t), keys[t]);
  std::vector<std::uint64_t> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  for (const std::uint32_t threads : {1u, 2u, 4u}) {
    INFO("threads " << threads);
    const auto order = discovery.order(count, parents_begin, parents_begin + parents, threads);
    REQUIRE(order.size() == count);
    std::vector<std::uint64_t> ordered;
    for (StateId id : order)
      ordered.push_back(discovery.key_of(id));
    CHECK(ordered == sorted);
  }
}
