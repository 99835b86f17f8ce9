// The level-synchronous frontier (checker/frontier.hpp).
#include <catch2/catch.hpp>

#include <vector>

#include "checker/frontier.hpp"

using checker::Frontier;
using checker::StateId;

TEST_CASE("Frontier: the level built becomes the one expanded", "[checker][frontier]") {
  Frontier frontier;
  CHECK(frontier.empty());
  CHECK(frontier.bytes() == 0);
  frontier.next() = {0, 1, 2}; // level 0
  CHECK(frontier.empty());
  frontier.advance();
  CHECK_FALSE(frontier.empty());
  CHECK(std::vector<StateId>(frontier.current().begin(), frontier.current().end()) ==
        std::vector<StateId>{0, 1, 2});
  CHECK(frontier.next().empty());
  frontier.next().push_back(3);
  frontier.advance();
  CHECK(std::vector<StateId>(frontier.current().begin(), frontier.current().end()) ==
        std::vector<StateId>{3});
  frontier.advance();
  CHECK(frontier.empty());
}

TEST_CASE("Frontier: both levels keep their memory, and count it", "[checker][frontier]") {
  Frontier frontier;
  frontier.next().reserve(100);
  frontier.advance();
  frontier.next().reserve(10);
  const std::size_t bytes = frontier.bytes();
  CHECK(bytes >= 110 * sizeof(StateId));
  frontier.advance();
  CHECK(frontier.bytes() == bytes);
}
