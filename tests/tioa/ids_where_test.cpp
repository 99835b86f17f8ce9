// Array queries (ids_where.hpp) and the runs of fields they read (field_run.hpp): the ids a
// query gives against the ids read one variable at a time, on random states.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "tioa/automaton.hpp"
#include "tioa/errors.hpp"
#include "tioa/field_run.hpp"
#include "tioa/ids_where.hpp"

using namespace tioa;

namespace {

std::uint64_t next_random(std::uint64_t& seed) {
  seed ^= seed << 13;
  seed ^= seed >> 7;
  seed ^= seed << 17;
  return seed;
}

} // namespace

TEST_CASE("field_of finds the field of every bit of a run without dividing") {
  for (std::uint32_t width = 1; width <= 63; ++width) {
    const FieldRun run = field_run_at(0, width, 63 / width);
    for (std::uint32_t bit = 0; bit < 64; ++bit)
      REQUIRE(run.field_of(bit) == bit / width);
  }
}

TEST_CASE("an id query gives the ids whose variable holds one of its values") {
  std::uint64_t seed = 0x9e3779b97f4a7c15ull;
  for (const int values : {2, 3, 5, 16}) // fields of 1, 2, 3 and 4 bits
    for (const int count : {1, 6, 15, 40})
      for (const int pad : {0, 7, 50}) // bits before the array: a run across two words
        for (const bool apart : {false, true}) {
          INFO(values << " values, " << count << " ids, " << pad << " bits before, "
                      << (apart ? "apart" : "side by side"));
          Automaton a("queried");
          for (int done = 0, k = 0; done < pad; ++k) {
            const int bits = std::min(20, pad - done);
            a.integer("pad" + std::to_string(k), 0, (1 << bits) - 1, 0);
            done += bits;
          }
          VariableArray<int> level;
          if (apart) { // another variable between its items
            level.first = 3;
            for (int i = 0; i < count; ++i) {
              level.items.push_back(
                  a.integer("level[" + std::to_string(i + 3) + "]", 1, values, 1));
              a.integer("other[" + std::to_string(i) + "]", 0, 1, 0);
            }
          } else {
            level = a.integers("level", ids(3, static_cast<std::size_t>(count) + 2), 1, values, 1);
          }
          const IdsWhere<int> one(level, {values});
          const IdsWhere<int> two(level, {1, values - 1});
          const int width = static_cast<int>(level.items.front().slot.width);
          CHECK(one.reads_at_once() == ((count == 1 || !apart) && count * width <= 63));
          std::vector<Word> words(a.words() + 1, 0);
          for (int round = 0; round < 40; ++round) {
            for (Word& w : words)
              w = next_random(seed);
            const State s(words.data(), 0);
            // Codes past the domain would be junk no state holds: keep every variable in it.
            std::vector<Word> fixed = words;
            State f(fixed.data(), 0);
            for (const auto& v : level)
              if (s.code(v.slot) >= v.slot.value_codes)
                f.set_code(v.slot, s.code(v.slot) % v.slot.value_codes);
            for (const IdsWhere<int>* query : {&one, &two}) {
              const std::vector<int> wanted =
                  query == &one ? std::vector<int>{values} : std::vector<int>{1, values - 1};
              std::vector<std::size_t> expected;
              for (std::size_t id = level.first; id < level.first + level.size(); ++id)
                for (const int v : wanted)
                  if (f[level[id]] == v) {
                    expected.push_back(id);
                    break;
                  }
              std::vector<std::size_t> got;
              query->for_each(f, [&](std::size_t id) { got.push_back(id); });
              REQUIRE(got == expected);
              REQUIRE(query->count(f) == expected.size());
              const std::size_t last = expected.empty() ? 0 : expected.back();
              REQUIRE(query->any(f, [&](std::size_t id) { return id == last; }) ==
                      !expected.empty());
              REQUIRE_FALSE(query->any(f, [](std::size_t) { return false; }));
            }
          }
        }
}

TEST_CASE("an id query over variables that may be ⊥ reads them one by one, as s[a[p]] does") {
  Automaton a("optional");
  VariableArray<int> target;
  target.first = 1;
  for (int i = 1; i <= 3; ++i)
    target.items.push_back(a.optional_integer("target[" + std::to_string(i) + "]", 0, 2, 1));
  const IdsWhere<int> at_two(target, {2});
  CHECK_FALSE(at_two.reads_at_once());
  std::vector<Word> words(a.words() + 1, 0);
  State s(words.data(), 0);
  s[target[1]] = 2;
  s[target[2]] = 0;
  s[target[3]] = 2;
  std::vector<std::size_t> got;
  at_two.for_each(s, [&](std::size_t id) { got.push_back(id); });
  CHECK(got == std::vector<std::size_t>{1, 3});
  s.set_bottom(target[2]);
  CHECK_THROWS_AS(at_two.count(s), ModelError);
}

TEST_CASE("an id query for a value outside the array's domain is a model error") {
  Automaton a("bad");
  const auto level = a.integers("level", 4, 0, 3, 0);
  CHECK_THROWS_AS(IdsWhere<int>(level, {4}), ModelError);
  CHECK_THROWS_AS(IdsWhere<int>(level, {}), ModelError);
}

TEST_CASE("an id query over side-by-side variables of different lowest values reads them one by "
          "one") {
  Automaton a("shifted");
  VariableArray<int> level;
  level.items.push_back(a.integer("level[0]", 0, 3, 0));
  level.items.push_back(a.integer("level[1]", 1, 4, 1)); // the same width, another code of 2
  const IdsWhere<int> at_two(level, {2});
  CHECK_FALSE(at_two.reads_at_once());
  std::vector<Word> words(a.words() + 1, 0);
  State s(words.data(), 0);
  s[level[0]] = 2;
  s[level[1]] = 2;
  CHECK(at_two.count(s) == 2);
  s[level[1]] = 3;
  CHECK(at_two.count(s) == 1);
}
