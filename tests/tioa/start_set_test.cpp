// Start sets (tioa/start_set.hpp): declared initial values, every valuation (U),
// a predicate (Start(A, L)) and a fixed list (R).
#include <catch2/catch.hpp>

#include "tests/tioa/helpers.hpp"

using namespace tioa;
using namespace tioa_test;

namespace {
enum class Mode { off, low, high };

// b = true, x ∈ 3..6 arbitrary, c ∈ {0, 1, 2, ⊥} arbitrary, m arbitrary, y = 1.
struct Mixed {
  Automaton a{"mixed"};
  Variable<bool> b = a.boolean("b", true);
  Variable<int> x = a.integer("x", 3, 6, std::nullopt);
  Variable<int> c = a.clock("c", 2, std::nullopt, true);
  Variable<Mode> m = a.enumeration<Mode>("m", {"off", "low", "high"}, std::nullopt);
  Variable<int> y = a.integer("y", 0, 1, 1);
};
} // namespace

TEST_CASE("start set: declared() fixes initial values and ranges over the others",
          "[tioa][start]") {
  const Mixed m;
  const auto list = enumerate(StartSet::declared(m.a.layout()), m.a.words());
  // 4 values of x × 4 codes of c (⊥ included) × 3 modes; b and y fixed.
  CHECK(list.size() == 4 * 4 * 3);
  CHECK(std::set<Words>(list.begin(), list.end()).size() == list.size());
  std::set<std::tuple<int, int, Mode>> combinations;
  for (const auto& w : list) {
    CHECK(value_of(w, m.b));
    CHECK(value_of(w, m.y) == 1);
    const int clock = view(w).is_bottom(m.c) ? -1 : value_of(w, m.c);
    combinations.emplace(value_of(w, m.x), clock, value_of(w, m.m));
  }
  CHECK(combinations.size() == 48);
  CHECK(combinations.count({3, -1, Mode::high}) == 1);
  CHECK(combinations.count({6, 2, Mode::off}) == 1);
  // An automaton's default start set is this one.
  CHECK(start_states(m.a) == list);
}

TEST_CASE("start set: every_valuation() is the product of the domain sizes", "[tioa][start]") {
  const Mixed m;
  const auto list = enumerate(StartSet::every_valuation(m.a.layout()), m.a.words());
  CHECK(list.size() == 2 * 4 * 4 * 3 * 2);
  CHECK(std::set<Words>(list.begin(), list.end()).size() == list.size());
  std::size_t bottoms = 0, b_false = 0;
  for (const auto& w : list) {
    bottoms += view(w).is_bottom(m.c);
    b_false += !value_of(w, m.b);
  }
  CHECK(bottoms == list.size() / 4);
  CHECK(b_false == list.size() / 2);

  // Single-valued and empty layouts have exactly one valuation.
  Automaton single("single");
  single.integer("k", 7, 7, std::nullopt);
  CHECK(enumerate(StartSet::every_valuation(single.layout()), single.words()).size() == 1);
  Automaton none("none");
  CHECK(enumerate(StartSet::every_valuation(none.layout()), none.words()).size() == 1);
}

TEST_CASE("start set: satisfying() keeps exactly the valuations of the predicate",
          "[tioa][start]") {
  const Mixed m;
  const auto x = m.x;
  const auto c = m.c;
  const auto start = StartSet::satisfying(
      m.a.layout(), [=](const State& s) { return s.get(x) % 2 == 0 && !s.is_bottom(c); },
      "x even, c set");
  CHECK(start.description() == "x even, c set");
  const auto list = enumerate(start, m.a.words());
  // b: 2, x ∈ {4, 6}: 2, c ∈ {0, 1, 2}: 3, m: 3, y: 2.
  CHECK(list.size() == 2 * 2 * 3 * 3 * 2);
  for (const auto& w : list) {
    CHECK(value_of(w, m.x) % 2 == 0);
    CHECK_FALSE(view(w).is_bottom(m.c));
  }
  const auto nothing = StartSet::satisfying(
      m.a.layout(), [](const State&) { return false; }, "empty");
  CHECK(enumerate(nothing, m.a.words()).empty());
}

TEST_CASE("start set: listed() visits exactly its states, in order", "[tioa][start]") {
  // Two 70-bit states, two words each.
  const std::vector<Word> states{0x0123456789abcdefULL, 0x2a, ~Word{0}, 0x3f};
  const auto start = StartSet::listed(70, 2, states, "two states");
  const auto list = enumerate(start, 2);
  REQUIRE(list.size() == 2);
  CHECK(list[0] == Words{0x0123456789abcdefULL, 0x2a});
  CHECK(list[1] == Words{~Word{0}, 0x3f});

  // Copied at a bit offset, with the bits around it left alone.
  Words buffer(4, ~Word{0});
  Words seen;
  start.enumerate(buffer.data(), 3, [&] {
    seen.push_back(bits_at(buffer, 0, 3));
    seen.push_back(bits_at(buffer, 3, 64));
    seen.push_back(bits_at(buffer, 67, 6));
    seen.push_back(bits_at(buffer, 73, 20));
  });
  CHECK(seen == Words{0b111, 0x0123456789abcdefULL, 0x2a, 0xfffff, //
                      0b111, ~Word{0}, 0x3f, 0xfffff});

  // A trailing partial state is not visited.
  const auto partial = StartSet::listed(70, 2, {1, 2, 3}, "one and a half");
  CHECK(enumerate(partial, 2).size() == 1);
}

TEST_CASE("start set: enumerating at a base leaves the bits below it alone", "[tioa][start]") {
  const Mixed m;
  Words buffer(m.a.words() + 2, 0);
  buffer[0] = 0b10110;
  std::size_t count = 0;
  bool intact = true;
  StartSet::every_valuation(m.a.layout()).enumerate(buffer.data(), 5, [&] {
    ++count;
    intact = intact && bits_at(buffer, 0, 5) == 0b10110;
  });
  CHECK(count == 192);
  CHECK(intact);
}

TEST_CASE("start set: copy_bits moves any run of bits between offsets", "[tioa][start]") {
  Words src{0xfedcba9876543210ULL, 0x0f0f0f0f0f0f0f0fULL, 0};
  Words dst(3, 0);
  copy_bits(dst.data(), 7, src.data(), 4, 100);
  for (std::uint32_t bit = 0; bit < 100; ++bit) {
    const auto got = bits_at(dst, 7 + bit, 1);
    const auto want = bits_at(src, 4 + bit, 1);
    if (got != want)
      FAIL("bit " << bit << " differs");
  }
  CHECK(bits_at(dst, 0, 7) == 0);
  CHECK(bits_at(dst, 107, 64) == 0);
  CHECK(bits_at(dst, 171, 21) == 0);
}
