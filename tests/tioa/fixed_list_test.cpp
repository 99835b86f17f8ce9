// tioa::FixedList: a list held in place for model effects (no allocation).
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tioa/fixed_list.hpp"

TEST_CASE("FixedList: pushes, erases in order, truncates, refuses past its capacity",
          "[fixed-list]") {
  tioa::FixedList<int, 4> list{5, 1, 4};
  CHECK(list.size() == 3);
  CHECK_FALSE(list.full());
  list.push_back(2);
  CHECK(list.full());
  CHECK_THROWS_AS(list.push_back(9), std::logic_error);
  CHECK(std::vector<int>(list.begin(), list.end()) == std::vector<int>{5, 1, 4, 2});
  list.erase(list.begin() + 1); // keeps the order of the others
  CHECK(std::vector<int>(list.begin(), list.end()) == std::vector<int>{5, 4, 2});
  list.truncate(1);
  CHECK(list.size() == 1);
  CHECK(list.front() == 5);
  list.push_back(7); // the places freed are reused
  CHECK(list[1] == 7);
  list.clear();
  CHECK(list.empty());
  // sort is stable: equal keys keep their order.
  tioa::FixedList<std::pair<int, char>, 5> pairs{{2, 'a'}, {1, 'b'}, {2, 'c'}, {0, 'd'}, {1, 'e'}};
  pairs.sort([](const auto& x, const auto& y) { return x.first < y.first; });
  std::string order;
  for (const auto& p : pairs)
    order += p.second;
  CHECK(order == "dbeac");
  CHECK(tioa::FixedList<int, 4>::capacity() == 4);
}
