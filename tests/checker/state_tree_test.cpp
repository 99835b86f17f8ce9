// The compressed store's tree (checker/state_tree.hpp): one key per state and one state per
// key, decoding gives the state back, parts that states share are held once, and threads
// that put states at once agree with one thread.
#include <catch2/catch.hpp>

#include <atomic>
#include <map>
#include <random>
#include <set>
#include <thread>
#include <vector>

#include "checker/state_tree.hpp"

using checker::StateTree;
using tioa::Word;
using Words = std::vector<Word>;

namespace {

// The key of `state`, growing the tables while they are out of room (one thread).
Word key_of(StateTree& tree, const Words& state) {
  std::vector<std::uint32_t> scratch(tree.scratch_size());
  for (;;) {
    if (const auto key = tree.insert(state.data(), scratch.data()))
      return *key;
    tree.make_room();
  }
}

Words decoded(const StateTree& tree, Word key) {
  Words out(tree.words(), 0);
  tree.decode(key, out.data());
  return out;
}

// States of `words` words: a few words drawn from small sets, some wide (top bits set, so
// they go to the tables), some left zero.
std::vector<Words> drawn_states(std::uint32_t words, std::size_t count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::vector<Words> states;
  for (std::size_t i = 0; i < count; ++i) {
    Words s(words, 0);
    for (std::uint32_t w = 0; w < words; ++w) {
      const Word small = random() % (w % 3 == 0 ? 2 : 7);
      s[w] = w % 2 == 0 ? small : (small << 40) | (Word{w} << 56);
    }
    states.push_back(s);
  }
  return states;
}

} // namespace

TEST_CASE("a state tree gives each distinct state one key and decodes it back", "[state_tree]") {
  for (const std::uint32_t words : {2u, 3u, 5u, 8u, 43u}) {
    StateTree tree(words);
    std::map<Words, Word> key_of_state;
    std::map<Word, Words> state_of_key;
    for (const Words& s : drawn_states(words, 5000, words)) {
      const Word key = key_of(tree, s);
      const auto [at, fresh] = key_of_state.emplace(s, key);
      CHECK(at->second == key); // the same state, the same key
      state_of_key.emplace(key, s);
      CHECK(decoded(tree, key) == s);
    }
    CHECK(state_of_key.size() == key_of_state.size()); // distinct states, distinct keys
    std::vector<std::uint32_t> scratch(tree.scratch_size());
    for (const auto& [s, key] : key_of_state) {
      const auto found = tree.find(s.data(), scratch.data());
      REQUIRE(found);
      CHECK(*found == key);
    }
    // A state never put is not found (a wide word no state has).
    Words other(words, 0);
    other[1] = ~Word{0};
    CHECK_FALSE(tree.find(other.data(), scratch.data()));
  }
}

TEST_CASE("a state tree holds shared parts once and small values not at all", "[state_tree]") {
  StateTree tree(4);
  // Words below 2^31 need no table; the pairs (1, 2) and (3, 4) are 2^32 and more.
  key_of(tree, {1, 2, 3, 4});
  CHECK(tree.parts() == 2);
  key_of(tree, {0, 0, 0, 9}); // pairs below 2^31 too
  CHECK(tree.parts() == 2);
  const std::uint64_t before = tree.parts();
  // The two halves of {w, 5, w, 5} are the same part: held once, at each position.
  const Word wide = Word{1} << 50;
  key_of(tree, {wide, 5, wide, 6});
  key_of(tree, {wide, 5, wide, 7});
  key_of(tree, {wide, 5, wide, 8});
  // The leaf `wide` at positions 0 and 2 (2 parts), the pair (wide, 5) at the left node
  // (1), the pairs (wide, 6..8) at the right node (3).
  CHECK(tree.parts() - before == 6);
}

TEST_CASE("threads that put states into a state tree at once get the keys of one thread",
          "[state_tree]") {
  const std::uint32_t words = 9;
  const auto states = drawn_states(words, 40000, 7);
  StateTree alone(words);
  std::set<Word> keys_alone;
  for (const Words& s : states)
    keys_alone.insert(key_of(alone, s));

  StateTree shared(words);
  shared.set_inserters(4);
  shared.make_room();
  std::vector<std::vector<Word>> keys(4);
  std::atomic<bool> out_of_room{false};
  // Rounds: the threads put their share until a table is out of room; between rounds the
  // tables grow while nobody puts (as the explorer's growth gate does).
  std::vector<std::size_t> next(4, 0);
  for (bool done = false; !done;) {
    out_of_room = false;
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < 4; ++t)
      threads.emplace_back([&, t] {
        std::vector<std::uint32_t> scratch(shared.scratch_size());
        for (std::size_t& i = next[t]; t + 4 * i < states.size(); ++i) {
          const auto key = shared.insert(states[t + 4 * i].data(), scratch.data());
          if (!key) {
            out_of_room = true;
            return;
          }
          keys[t].push_back(*key);
        }
      });
    for (auto& thread : threads)
      thread.join();
    done = !out_of_room;
    if (!done)
      shared.make_room();
  }
  std::set<Word> keys_shared;
  for (const auto& k : keys)
    keys_shared.insert(k.begin(), k.end());
  CHECK(keys_shared.size() == keys_alone.size());
  CHECK(shared.parts() == alone.parts());
  for (std::size_t t = 0; t < 4; ++t)
    for (std::size_t i = 0; i < keys[t].size(); ++i)
      CHECK(decoded(shared, keys[t][i]) == states[t + 4 * i]);
}

TEST_CASE("a state tree's key made near another state is the key made from scratch",
          "[state_tree]") {
  const std::uint32_t words = 11;
  const auto states = drawn_states(words, 3000, 3);
  StateTree tree(words);
  std::vector<std::uint32_t> near_ids(tree.scratch_size()), ids(tree.scratch_size());
  for (std::size_t i = 1; i < states.size(); ++i) {
    // `near` is a stored state, decoded with its nodes' ids as the explorer does; the next
    // state differs from it in a few words (or many).
    const Word near_key = key_of(tree, states[i - 1]);
    Words near(words, 0);
    tree.decode(near_key, near.data(), near_ids.data());
    Words next = near;
    for (std::uint32_t w = 0; w < words; ++w)
      if ((i + w) % (i % 4 + 2) == 0)
        next[w] = states[i][w];
    std::optional<Word> made;
    while (!(made = tree.insert_near(next.data(), near.data(), near_ids.data(), ids.data())))
      tree.make_room();
    CHECK(*made == key_of(tree, next));
    CHECK(decoded(tree, *made) == next);
  }
}
