// State views (tioa/state.hpp): typed reads and writes of packed variables.
#include <catch2/catch.hpp>

#include "tests/tioa/helpers.hpp"

using namespace tioa;
using namespace tioa_test;
using Catch::Contains;

namespace {
enum class Phase { idle, trying, critical };
} // namespace

TEST_CASE("state: booleans read back what was written", "[tioa][state]") {
  Automaton a("bools");
  const auto p = a.boolean("p", false);
  const auto q = a.boolean("q", std::nullopt);
  Words w = blank(a);
  State s(w.data(), 0);
  s[p] = true;
  CHECK(s.get(p));
  CHECK_FALSE(s.get(q));
  s[q] = true;
  s[p] = false;
  CHECK_FALSE(s.get(p));
  CHECK(s.get(q));
  // p is bit 0 and q bit 1.
  CHECK(w[0] == 0b10);
}

TEST_CASE("state: bounded integers with a non-zero lower bound", "[tioa][state]") {
  Automaton a("ints");
  const auto x = a.integer("x", 3, 6, 4);
  const auto t = a.integer("t", -2, 1, std::nullopt);
  Words w = blank(a);
  State s(w.data(), 0);
  for (int v = 3; v <= 6; ++v) {
    s[x] = v;
    CHECK(s.get(x) == v);
    // Stored as the offset from the lower bound.
    CHECK(s.code(x.slot) == static_cast<std::uint64_t>(v - 3));
  }
  for (int v = -2; v <= 1; ++v) {
    s[t] = v;
    CHECK(s.get(t) == v);
    CHECK(s.get(x) == 6);
  }
  // A read through a const view gives the value itself.
  const State& c = s;
  CHECK(c[x] == 6);
  CHECK(c[t] == 1);
}

TEST_CASE("state: a value outside the domain is a ModelError naming the variable",
          "[tioa][state]") {
  Automaton a("domains");
  const auto x = a.integer("x", 3, 6, 4);
  const auto e = a.enumeration<Phase>("phase", {"idle", "trying", "critical"}, Phase::idle);
  const auto c = a.clock("c", 2, 0);
  Words w = blank(a);
  State s(w.data(), 0);
  s[x] = 5;
  CHECK_THAT(model_error([&] { s[x] = 2; }), Contains("'x'") && Contains("outside the domain"));
  CHECK_THAT(model_error([&] { s[x] = 7; }), Contains("'x'") && Contains("7"));
  CHECK_THAT(model_error([&] { s[e] = static_cast<Phase>(3); }), Contains("'phase'"));
  CHECK_THAT(model_error([&] { s[c] = 3; }), Contains("'c'"));
  CHECK_THAT(model_error([&] { s[c] = -1; }), Contains("'c'"));
  // A rejected write leaves the state as it was.
  CHECK(s.get(x) == 5);
  CHECK(s.get(e) == Phase::idle);
}

TEST_CASE("state: enumerations", "[tioa][state]") {
  Automaton a("enums");
  const auto before = a.boolean("before", std::nullopt);
  const auto e = a.enumeration<Phase>("phase", {"idle", "trying", "critical"}, Phase::idle);
  const auto after = a.boolean("after", std::nullopt);
  Words w = blank(a);
  State s(w.data(), 0);
  s[before] = true;
  s[after] = true;
  for (Phase v : {Phase::critical, Phase::idle, Phase::trying}) {
    s[e] = v;
    CHECK(s.get(e) == v);
    CHECK(s.get(before));
    CHECK(s.get(after));
  }
  CHECK(a.layout().find("phase")->render_code(2) == "critical");
}

TEST_CASE("state: clocks advance one quantum and saturate at the cap", "[tioa][state]") {
  Automaton a("clocks");
  const auto c = a.clock("c", 3, 0);
  const auto neighbour = a.integer("n", 0, 7, 5);
  Words w = blank(a);
  State s(w.data(), 0);
  s[neighbour] = 5;
  std::vector<int> seen;
  for (int i = 0; i < 6; ++i) {
    seen.push_back(s.get(c));
    s.advance(c);
  }
  CHECK(seen == std::vector<int>{0, 1, 2, 3, 3, 3});
  CHECK(s.get(neighbour) == 5);
}

TEST_CASE("state: a clock at ⊥ stays ⊥ and reading it is a ModelError", "[tioa][state]") {
  Automaton a("bottom");
  const auto c = a.clock("timer", 2, std::nullopt, true);
  const auto plain = a.clock("plain", 2, 0);
  Words w = blank(a);
  State s(w.data(), 0);
  s[c] = 2;
  CHECK_FALSE(s.is_bottom(c));
  s.set_bottom(c);
  CHECK(s.is_bottom(c));
  s.advance(c);
  CHECK(s.is_bottom(c));
  CHECK_THAT(model_error([&] { (void)s.get(c); }), Contains("'timer'") && Contains("⊥"));
  CHECK_THAT(model_error([&] {
               int v = s[c];
               (void)v;
             }),
             Contains("'timer'"));
  // ⊥ is not a value that can be written as a number: cap + 1 is outside the domain.
  CHECK_THAT(model_error([&] { s[c] = 3; }), Contains("'timer'"));
  CHECK(s.is_bottom(c));
  // A clock without ⊥ refuses it.
  CHECK_THAT(model_error([&] { s.set_bottom(plain); }), Contains("'plain'"));
  // Leaving ⊥ by assignment.
  s[c] = 0;
  CHECK_FALSE(s.is_bottom(c));
  s.advance(c);
  CHECK(s.get(c) == 1);
  // A clock at its cap with ⊥ saturates instead of becoming ⊥.
  s[c] = 2;
  s.advance(c);
  CHECK(s.get(c) == 2);
  CHECK_FALSE(s.is_bottom(c));
}

TEST_CASE("state: variables that straddle a 64-bit word boundary", "[tioa][state]") {
  Automaton a("wide");
  const auto low = a.integers("low", 20, 0, 7, 0);          // bits 0..59
  const auto flag = a.boolean("flag", false);               // bit 60
  const auto across = a.integer("across", -100, -85, -100); // 4 bits: 61..64
  const auto mid = a.integers("mid", 20, 0, 7, 0);          // bits 65..124
  const auto far = a.integer("far", 0, 99, 0);              // 7 bits: 125..131
  const auto tail = a.boolean("tail", false);               // bit 132

  REQUIRE(across.slot.offset == 61);
  REQUIRE(across.slot.width == 4);
  REQUIRE(far.slot.offset == 125);
  REQUIRE(far.slot.width == 7);
  REQUIRE(tail.slot.offset == 132);
  REQUIRE(a.words() == 3);

  Words w = blank(a);
  State s(w.data(), 0);
  auto fill = [&] {
    for (std::size_t i = 0; i < low.size(); ++i)
      s[low[i]] = static_cast<int>((i * 5 + 3) % 8);
    for (std::size_t i = 0; i < mid.size(); ++i)
      s[mid[i]] = static_cast<int>((i * 3 + 1) % 8);
    s[flag] = true;
    s[tail] = true;
  };
  auto neighbours_intact = [&] {
    bool ok = s.get(flag) && s.get(tail);
    for (std::size_t i = 0; i < low.size(); ++i)
      ok = ok && s.get(low[i]) == static_cast<int>((i * 5 + 3) % 8);
    for (std::size_t i = 0; i < mid.size(); ++i)
      ok = ok && s.get(mid[i]) == static_cast<int>((i * 3 + 1) % 8);
    return ok;
  };
  fill();
  for (int v = -100; v <= -85; ++v) {
    s[across] = v;
    CHECK(s.get(across) == v);
    CHECK(neighbours_intact());
  }
  for (int v = 0; v <= 99; ++v) {
    s[far] = v;
    CHECK(s.get(far) == v);
  }
  CHECK(neighbours_intact());
  CHECK(s.get(across) == -85);

  // Code 0b1111 of `across`: three bits at the top of word 0, one at the bottom of word 1.
  Words zero = blank(a);
  State z(zero.data(), 0);
  z[across] = -85;
  CHECK(zero[0] == (Word{0b111} << 61));
  CHECK(zero[1] == Word{1});
  z[far] = 99; // 0b1100011 at bits 125..131: 0b011 in word 1, 0b1100 in word 2
  CHECK(zero[1] == ((Word{0b011} << 61) | Word{1}));
  CHECK(zero[2] == Word{0b1100});
  z[across] = -100;
  CHECK(zero[0] == 0);
  CHECK(zero[1] == (Word{0b011} << 61));
  CHECK(z.get(far) == 99);
}

TEST_CASE("state: a view placed further on reads the component's own variables", "[tioa][state]") {
  Automaton a("part");
  const auto x = a.integer("x", 1, 4, 1);
  const auto b = a.boolean("b", false);
  Words w(3, 0);
  State whole(w.data(), 0);
  State part = whole.at(62); // the part straddles the first word boundary
  part[x] = 4;
  part[b] = true;
  CHECK(part.get(x) == 4);
  CHECK(part.get(b));
  CHECK(w[0] == (Word{0b11} << 62));
  CHECK(w[1] == Word{0b1});
  CHECK(State(w.data(), 62).get(x) == 4);
}

TEST_CASE("state: one variable assigned from another", "[tioa][state]") {
  Automaton a("copy");
  const auto x = a.integers("x", 2, 2, 5, std::nullopt);
  Words w = blank(a);
  State s(w.data(), 0);
  s[x[0]] = 5;
  s[x[1]] = 2;
  s[x[1]] = s[x[0]];
  CHECK(s.get(x[1]) == 5);
  CHECK(s.get(x[0]) == 5);
}
