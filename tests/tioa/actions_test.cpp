// Action signatures and parameter boxes (tioa/actions.hpp).
#include <catch2/catch.hpp>

#include "tests/tioa/helpers.hpp"

using namespace tioa;

namespace {
std::vector<std::vector<int>> points(const std::vector<ParamRange>& box) {
  std::vector<std::vector<int>> out;
  for_each_params(box, [&](const Params& p) {
    std::vector<int> point;
    for (std::size_t i = 0; i < p.size; ++i)
      point.push_back(p[i]);
    out.push_back(point);
  });
  return out;
}

Params params(std::initializer_list<int> values) {
  Params p;
  for (int v : values)
    p.values[p.size++] = v;
  return p;
}
} // namespace

TEST_CASE("for_each_params: every point of a box in lexicographic order", "[tioa][actions]") {
  const auto list = points({{"i", 0, 1}, {"j", -1, 1}});
  CHECK(list == std::vector<std::vector<int>>{{0, -1}, {0, 0}, {0, 1}, {1, -1}, {1, 0}, {1, 1}});

  // Three dimensions: the count is the product of the ranges.
  CHECK(points({{"a", 1, 3}, {"b", 0, 0}, {"c", 5, 8}}).size() == 3 * 1 * 4);
  CHECK(points({{"a", 2, 6}}) == std::vector<std::vector<int>>{{2}, {3}, {4}, {5}, {6}});
}

TEST_CASE("for_each_params: an empty box is one call without parameters", "[tioa][actions]") {
  const auto list = points({});
  REQUIRE(list.size() == 1);
  CHECK(list[0].empty());
}

TEST_CASE("for_each_params: a box with an empty range has no points", "[tioa][actions]") {
  CHECK(points({{"i", 0, 3}, {"j", 2, 1}}).empty());
  CHECK(points({{"i", 1, 0}}).empty());
}

TEST_CASE("signature: contains, overlaps and labels", "[tioa][actions]") {
  const ActionSignature move{"move", ActionKind::output, {{"i", 1, 3}, {"j", 0, 0}}};
  CHECK(move.contains(params({1, 0})));
  CHECK(move.contains(params({3, 0})));
  CHECK_FALSE(move.contains(params({0, 0})));
  CHECK_FALSE(move.contains(params({2, 1})));
  CHECK_FALSE(move.contains(params({2})));       // wrong arity
  CHECK_FALSE(move.contains(params({2, 0, 0}))); // wrong arity

  const ActionSignature touching{"move", ActionKind::input, {{"i", 3, 5}, {"j", -2, 0}}};
  const ActionSignature apart{"move", ActionKind::input, {{"i", 4, 5}, {"j", 0, 0}}};
  const ActionSignature other_name{"jump", ActionKind::input, {{"i", 1, 3}, {"j", 0, 0}}};
  const ActionSignature other_arity{"move", ActionKind::input, {{"i", 1, 3}}};
  CHECK(move.overlaps(touching));
  CHECK(touching.overlaps(move));
  CHECK_FALSE(move.overlaps(apart));
  CHECK_FALSE(move.overlaps(other_name));
  CHECK_FALSE(move.overlaps(other_arity));

  CHECK(move.label(params({2, 0})) == "move(2,0)");
  const ActionSignature bare{"tock", ActionKind::internal, {}};
  CHECK(bare.label(Params{}) == "tock");
  CHECK(std::string(to_string(ActionKind::input)) == "input");
  CHECK(std::string(to_string(ActionKind::output)) == "output");
  CHECK(std::string(to_string(ActionKind::internal)) == "internal");
}
