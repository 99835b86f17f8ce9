// Scenarios drawn at random (models/path_reservation/random_scenario.hpp): one seed is one
// scenario, every draw passes the model's checks and the rules of the draw, and a drawn
// scenario written as a file reads back to itself.
#include <catch2/catch.hpp>

#include <sstream>

#include "models/path_reservation/random_scenario.hpp"
#include "models/path_reservation/scenario_file.hpp"

using path_reservation::Cell;
using path_reservation::random_scenario;
using path_reservation::RandomScenarioSpec;

namespace {

RandomScenarioSpec spec(std::uint64_t seed, int robots, int chunks, int plane) {
  RandomScenarioSpec s;
  s.seed = seed;
  s.robots = robots;
  s.chunks = chunks;
  s.plane = plane;
  return s;
}

} // namespace

TEST_CASE("path-reservation: a seed draws one scenario, valid by every rule",
          "[path-reservation][random]") {
  CHECK(random_scenario(spec(7, 3, 2, 4)).paths == random_scenario(spec(7, 3, 2, 4)).paths);
  CHECK(random_scenario(spec(7, 3, 2, 4)).paths != random_scenario(spec(8, 3, 2, 4)).paths);
  for (std::uint64_t seed = 1; seed <= 200; ++seed)
    for (const auto& [robots, chunks, plane] :
         {std::tuple{2, 1, 3}, std::tuple{3, 2, 4}, std::tuple{5, 3, 5}, std::tuple{6, 2, 8}}) {
      INFO("seed " << seed << ", " << robots << " robots");
      const auto s = random_scenario(spec(seed, robots, chunks, plane));
      REQUIRE(s.robots() == robots);
      CHECK_FALSE(path_reservation::check_scenario(s));
      CHECK(s.range == plane);
      path_reservation::Plane grid(plane, plane);
      path_reservation::CellSet ends = 0;
      for (const auto& path : s.paths) {
        CHECK(static_cast<int>(path.size()) == chunks + 1);
        for (std::size_t k = 0; k + 1 < path.size(); ++k)
          CHECK_FALSE(path[k] == path[k + 1]);
        CHECK((ends & grid.bit(path.back())) == 0);
        ends |= grid.bit(path.back());
      }
      // Near enough to meet: with more than one robot, every path shares a cell with another.
      for (int r = 0; r < robots && robots > 1; ++r) {
        bool meets = false;
        for (int other = 0; other < robots; ++other)
          for (std::size_t k = 0; other != r && k + 1 < s.paths[r].size(); ++k)
            for (std::size_t l = 0; l + 1 < s.paths[other].size(); ++l)
              meets = meets || (grid.zone(s.paths[r][k], s.paths[r][k + 1]).all() &
                                grid.zone(s.paths[other][l], s.paths[other][l + 1]).all()) != 0;
        CHECK(meets);
      }
    }
}

TEST_CASE("path-reservation: sizes a draw cannot meet are refused in one line",
          "[path-reservation][random]") {
  CHECK_THROWS_WITH(random_scenario(spec(1, 7, 2, 4)), "robots must be in 1..6");
  CHECK_THROWS_WITH(random_scenario(spec(1, 3, 8, 4)), "chunks must be in 1..7");
  CHECK_THROWS_WITH(random_scenario(spec(1, 3, 2, 9)),
                    "plane must be in 2..8 (a side of at most 8 cells: 64 cells)");
  CHECK_THROWS_WITH(random_scenario(spec(1, 5, 2, 2)), "more robots than cells");
}

TEST_CASE("path-reservation: a drawn scenario written as a file reads back to itself",
          "[path-reservation][random]") {
  const auto s = random_scenario(spec(3, 4, 3, 5));
  std::istringstream in(path_reservation::scenario_file_text(s));
  const auto back = path_reservation::parse_scenario(in, "drawn.txt");
  CHECK(back.name == s.name);
  CHECK(back.description == s.description);
  CHECK(back.width == s.width);
  CHECK(back.height == s.height);
  CHECK(back.range == s.range);
  CHECK(back.paths == s.paths);
}
