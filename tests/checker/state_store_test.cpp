// The visited-state store (checker/state_store.hpp): dense ids in insertion order,
// duplicates, growth, and states whose hash tags collide.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <mutex>
#include <random>
#include <unordered_map>
#include <vector>

#include "checker/state_store.hpp"

using checker::hash_state;
using checker::StateId;
using checker::StateStore;
using tioa::Word;
using Words = std::vector<Word>;

namespace {

std::pair<StateId, bool> insert(StateStore& store, const Words& s) {
  return store.insert(s.data(), hash_state(s.data(), store.words()));
}

std::optional<StateId> find(const StateStore& store, const Words& s) {
  return store.find(s.data(), hash_state(s.data(), store.words()));
}

Words stored(const StateStore& store, StateId id) {
  return Words(store.state(id), store.state(id) + store.words());
}

// Pairs of one-word states whose hashes have the same top 32 bits (so the same tag, which
// the table takes from those bits, at every size), found by a deterministic birthday search.
std::vector<std::pair<Word, Word>> tag_collisions(std::size_t wanted) {
  std::unordered_map<std::uint32_t, Word> seen;
  std::vector<std::pair<Word, Word>> out;
  for (Word w = 0; out.size() < wanted; ++w) {
    const auto tag = static_cast<std::uint32_t>(hash_state(&w, 1) >> 32);
    const auto [it, fresh] = seen.emplace(tag, w);
    if (!fresh)
      out.emplace_back(it->second, w);
  }
  return out;
}

} // namespace

TEST_CASE("hash_state depends on every word and on the length", "[checker][state_store]") {
  const Words a{1, 2, 3}, b{1, 2, 4}, c{0, 2, 3};
  CHECK(hash_state(a.data(), 3) == hash_state(Words{1, 2, 3}.data(), 3));
  CHECK(hash_state(a.data(), 3) != hash_state(b.data(), 3));
  CHECK(hash_state(a.data(), 3) != hash_state(c.data(), 3));
  CHECK(hash_state(a.data(), 2) != hash_state(a.data(), 3));
}

TEST_CASE("insert and find", "[checker][state_store]") {
  StateStore store(2);
  CHECK(store.words() == 2);
  CHECK(store.size() == 0);
  const Words a{7, 0}, b{0, 7}, c{7, 7};
  CHECK_FALSE(find(store, a));

  CHECK(insert(store, a) == std::make_pair(StateId{0}, true));
  CHECK(store.size() == 1);
  CHECK(find(store, a) == StateId{0});
  CHECK_FALSE(find(store, b));
  CHECK(stored(store, 0) == a);

  CHECK(insert(store, b) == std::make_pair(StateId{1}, true));
  CHECK(insert(store, a) == std::make_pair(StateId{0}, false)); // a duplicate keeps its id
  CHECK(insert(store, c) == std::make_pair(StateId{2}, true));
  CHECK(store.size() == 3);
  CHECK(find(store, b) == StateId{1});
  CHECK(find(store, c) == StateId{2});
  CHECK(stored(store, 1) == b);
  CHECK(stored(store, 2) == c);
}

TEST_CASE("the all-zero state is a state like any other", "[checker][state_store]") {
  // Empty table slots are 0: a zero state (and a zero hash) must not be mistaken for one.
  StateStore store(1);
  const Words zero{0};
  CHECK(insert(store, zero) == std::make_pair(StateId{0}, true));
  CHECK(find(store, zero) == StateId{0});
  CHECK(insert(store, zero).second == false);
  const Words one{1};
  CHECK(store.insert(one.data(), 0) == std::make_pair(StateId{1}, true));
  CHECK(store.find(one.data(), 0) == StateId{1});
}

TEST_CASE("ids are dense and in insertion order; duplicates change nothing",
          "[checker][state_store]") {
  StateStore store(1);
  std::vector<Words> states;
  for (Word w = 0; w < 5000; ++w)
    states.push_back({w * 0x9e3779b97f4a7c15ull}); // distinct, scattered
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto [id, fresh] = insert(store, states[i]);
    REQUIRE(fresh);
    REQUIRE(id == i);
  }
  const std::size_t memory = store.memory_bytes();
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto [id, fresh] = insert(store, states[i]);
    REQUIRE_FALSE(fresh);
    REQUIRE(id == i);
  }
  CHECK(store.size() == states.size());
  CHECK(store.memory_bytes() == memory);
  for (std::size_t i = 0; i < states.size(); ++i)
    REQUIRE(stored(store, static_cast<StateId>(i)) == states[i]);
}

TEST_CASE("growth past many rehashes keeps every id", "[checker][state_store]") {
  // 10^5 random three-word states: the table (1024 slots at first) doubles about 8 times.
  constexpr std::size_t count = 100000;
  std::mt19937_64 random(20240611);
  StateStore store(3);
  std::map<Words, StateId> expected;
  std::vector<Words> order;
  const std::size_t initial_memory = store.memory_bytes();
  while (order.size() < count) {
    // Small words so that some draws repeat: duplicates are part of the workload.
    const Words s{random() % 64, random() % 64, random() % 32};
    const auto [it, fresh] = expected.emplace(s, static_cast<StateId>(expected.size()));
    const auto [id, inserted] = insert(store, s);
    REQUIRE(inserted == fresh);
    REQUIRE(id == it->second);
    order.push_back(s);
  }
  CHECK(store.size() == expected.size());
  CHECK(expected.size() > 50000); // the workload mixes fresh states and duplicates
  CHECK(expected.size() < count);
  CHECK(store.memory_bytes() > initial_memory);
  for (const auto& [s, id] : expected) {
    REQUIRE(find(store, s) == id);
    REQUIRE(stored(store, id) == s);
  }
  // States never inserted are not found (the third word is < 32 for every stored one).
  for (Word w = 0; w < 1000; ++w)
    REQUIRE_FALSE(find(store, Words{w % 64, w / 64, 32 + w % 7}));
}

TEST_CASE("states with equal hash tags stay apart", "[checker][state_store]") {
  SECTION("the very same hash for different states") {
    // The caller's hash decides the slot and the tag; equality is still by content.
    StateStore store(2);
    for (Word w = 0; w < 200; ++w) {
      const Words s{w, ~w};
      REQUIRE(store.insert(s.data(), 0x1234567800000000ull) ==
              std::make_pair(static_cast<StateId>(w), true));
    }
    for (Word w = 0; w < 200; ++w) {
      const Words s{w, ~w};
      REQUIRE(store.find(s.data(), 0x1234567800000000ull) == static_cast<StateId>(w));
      REQUIRE(store.insert(s.data(), 0x1234567800000000ull).second == false);
    }
    const Words absent{200, ~Word{200}};
    CHECK_FALSE(store.find(absent.data(), 0x1234567800000000ull));
  }

  SECTION("real tag collisions of hash_state, through growth") {
    const auto pairs = tag_collisions(12);
    REQUIRE(pairs.size() == 12);
    for (const auto& [a, b] : pairs) {
      REQUIRE(a != b);
      REQUIRE((hash_state(&a, 1) >> 32) == (hash_state(&b, 1) >> 32));
    }
    StateStore store(1);
    std::vector<Word> order;
    for (const auto& [a, b] : pairs) {
      CHECK(insert(store, {a}).first == order.size());
      order.push_back(a);
      CHECK(find(store, {a}) == static_cast<StateId>(order.size() - 1));
      CHECK_FALSE(find(store, {b})); // same tag, different state: not found
      CHECK(insert(store, {b}).first == order.size());
      order.push_back(b);
    }
    // Filler states make the table grow several times around the colliding pairs.
    for (Word w = 0; order.size() < 20000; ++w) {
      const Word filler = (w << 40) | 0xabcdefu;
      if (insert(store, {filler}).second)
        order.push_back(filler);
    }
    CHECK(store.size() == order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      REQUIRE(find(store, {order[i]}) == static_cast<StateId>(i));
  }
}

TEST_CASE("growth_bytes: what the next insert allocates, 0 when it allocates nothing",
          "[checker][state_store][memory_budget]") {
  StateStore store(2);
  int growths = 0;
  for (Word w = 0; w < 5000; ++w) {
    const std::size_t growth = store.growth_bytes();
    const std::size_t before = store.memory_bytes();
    insert(store, {w, ~w});
    const std::size_t after = store.memory_bytes();
    if (growth == 0) {
      CHECK(after == before);
    } else {
      ++growths;
      CHECK(after > before);
      CHECK(after <= before + growth); // the old buffer goes once the new one is filled
    }
  }
  CHECK(growths > 4); // the arena and the table each grew a few times
}

TEST_CASE("find_or_insert hands out ids a block at a time; reorder renumbers and drops the holes",
          "[checker][state_store]") {
  StateStore store(1);
  for (Word w = 0; w < 10; ++w)
    insert(store, {w});
  store.set_inserters(1, 4);
  store.make_room(8);
  StateStore::IdBlock ids{0, 0, 4};
  std::vector<std::pair<StateId, std::uint32_t>> fresh;
  for (Word w : {100, 101, 5}) {
    const Words s{w};
    const auto claim =
        store.find_or_insert(s.data(), hash_state(s.data(), 1), ids,
                             [&](StateId id, std::uint32_t slot) { fresh.emplace_back(id, slot); });
    CHECK(claim.kind == (w == 5 ? StateStore::Claim::Kind::known : StateStore::Claim::Kind::fresh));
  }
  REQUIRE(fresh.size() == 2);
  CHECK(fresh[0].first == 10);
  CHECK(fresh[1].first == 11);
  CHECK(store.size() == 14); // ids 12 and 13 are the block's unused end
  CHECK(fresh[0].second == store.slot_of(10));
  const std::vector<StateId> order{11, 10};
  store.reorder(10, order, nullptr);
  CHECK(store.size() == 12);
  CHECK(stored(store, 10) == Words{101});
  CHECK(stored(store, 11) == Words{100});
  CHECK(find(store, {100}) == StateId{11});
  CHECK(find(store, {101}) == StateId{10});
  CHECK(find(store, {5}) == StateId{5});
  CHECK(insert(store, {102}) == std::make_pair(StateId{12}, true));
}

TEST_CASE("reorder in place moves the states as the copy does, holes included",
          "[checker][state_store]") {
  // Two inserters take blocks of 8 ids in turn, so the level has holes at the end of
  // blocks; the order is a shuffle of its states.
  for (const bool in_place : {false, true}) {
    CAPTURE(in_place);
    StateStore store(3);
    for (Word w = 0; w < 20; ++w)
      insert(store, {w, w, w});
    store.set_inserters(2, 8);
    store.make_room(400);
    std::vector<StateStore::IdBlock> blocks(2, StateStore::IdBlock{0, 0, 8});
    std::map<StateId, Words> level; // id -> state, as inserted
    for (Word w = 1000; w < 1300; ++w) {
      const Words s{w, w * 3, w ^ 0x55};
      store.find_or_insert(s.data(), hash_state(s.data(), 3), blocks[(w / 7) % 2],
                           [&](StateId id, std::uint32_t) { level[id] = s; });
    }
    REQUIRE(store.size() > 20 + level.size()); // there are holes
    std::vector<StateId> order;
    for (const auto& entry : level)
      order.push_back(entry.first);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    store.reorder(20, order, nullptr, in_place);
    REQUIRE(store.size() == 20 + order.size());
    for (StateId w = 0; w < 20; ++w)
      CHECK(stored(store, w) == Words{w, w, w});
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Words& s = level.at(order[i]);
      CHECK(stored(store, static_cast<StateId>(20 + i)) == s);
      CHECK(find(store, s) == StateId(20 + i));
    }
  }
}

TEST_CASE("truncate forgets the states after the first n", "[checker][state_store]") {
  StateStore store(1);
  for (Word w = 0; w < 3000; ++w)
    insert(store, {w * 7});
  store.truncate(1000);
  CHECK(store.size() == 1000);
  CHECK(find(store, {999 * 7}) == StateId{999});
  CHECK_FALSE(find(store, {1000 * 7}));
  CHECK(insert(store, {1000 * 7}) == std::make_pair(StateId{1000}, true));
}

TEST_CASE("a growing table says where it puts each state, with its holes left out",
          "[checker][state_store]") {
  StateStore store(1);
  store.set_inserters(2, 4);
  StateStore::IdBlock ids{0, 0, 4};
  for (Word w = 0; w < 500; ++w) {
    const Words s{w * 7919};
    StateStore::Claim claim;
    while ((claim = store.find_or_insert(s.data(), hash_state(s.data(), 1), ids,
                                         [](StateId, std::uint32_t) {}))
               .kind == StateStore::Claim::Kind::full)
      store.make_room(1);
    REQUIRE(claim.kind == StateStore::Claim::Kind::fresh);
  }
  // Ids from 100 on: every third one is a hole (no state is looked up at it).
  auto holds = [](StateId id) { return id < 100 || id % 3 != 0; };
  std::map<StateId, std::uint32_t> placed;
  std::mutex placing; // (the table may be filled by two threads)
  bool twice = false;
  const std::uint64_t tables = store.tables_built();
  store.make_room(5000, holds, [&](StateId id, std::uint32_t slot) {
    const std::lock_guard<std::mutex> lock(placing);
    twice = twice || !placed.emplace(id, slot).second;
  });
  CHECK_FALSE(twice);
  REQUIRE(store.tables_built() > tables);
  std::size_t held = 0, wrong = 0;
  for (StateId id = 0; id < store.size(); ++id) {
    if (!holds(id)) {
      CHECK(placed.count(id) == 0);
      continue;
    }
    ++held;
    wrong += placed.count(id) == 0 || placed.at(id) != store.slot_of(id);
  }
  CHECK(placed.size() == held);
  CHECK(wrong == 0);
}
