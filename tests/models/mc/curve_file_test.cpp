// Curve files (models/mc/curve_file.hpp) and round configurations (round_config.hpp): what
// they read, the one-line errors with the line to blame, and a configuration written and
// read back.
#include <catch2/catch.hpp>

#include <sstream>

#include "models/mc/curve_file.hpp"
#include "models/mc/round_config.hpp"

namespace {

mc::CurveFile parse(const std::string& text) {
  std::istringstream in(text);
  return mc::parse_curve_file(in, "c.txt");
}

std::string error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

} // namespace

TEST_CASE("a curve file gives q as a matrix, '.' for regions off the curve") {
  const mc::CurveFile file = parse("# zigzag\n. 1 .\n1 2 1   # the middle row\n\n. . 3\n");
  CHECK(file.m == 3);
  CHECK(file.q == std::vector<std::int64_t>{0, 1, 0, 1, 2, 1, 0, 0, 3});
  CHECK(!file.polyline);
}

TEST_CASE("a curve file gives a polyline whose q the tool computes") {
  // Along the middle of row 0 from x = 1/2 to 5/2, then down the middle of column 2 to
  // y = 5/2: region (0,0) holds 1/2, (0,1) 1, (0,2) 1/2 + 1/2, (1,2) 1, (2,2) 1/2; σ = 1/4.
  const mc::CurveFile file =
      parse("grid 3\nsigma 1/4\npolyline (1/2,1/2) (5/2,1/2)\npolyline (5/2,5/2)\n");
  CHECK(file.m == 3);
  CHECK(file.sigma == mc::Rational(1, 4));
  REQUIRE(file.polyline);
  CHECK(file.q == std::vector<std::int64_t>{2, 4, 4, 0, 0, 4, 0, 0, 2});
  // Closed: the square through the centres of the outer ring, 1 in each of its 8 regions.
  const mc::CurveFile ring =
      parse("grid 3\npolyline (1/2,1/2) (5/2,1/2) (5/2,5/2) (1/2,5/2)\nclosed\n");
  CHECK(ring.q == std::vector<std::int64_t>{1, 1, 1, 1, 0, 1, 1, 1, 1});
}

TEST_CASE("a bad curve file is one line naming the file and the line") {
  CHECK(error_of("1 2\n3\n") == "c.txt:2: this row has 1 entries, the first row (line 1) 2");
  CHECK(error_of("1 2\n3 4\n5 6\n") ==
        "c.txt:3: the q matrix has 3 rows of 2 entries: it must be square (m rows of m)");
  CHECK(error_of("1 x\n") == "c.txt:1: q: 'x' is not a whole number in 0..1000000");
  CHECK(error_of(". -1\n1 1\n") == "c.txt:1: q: '-1' is not a whole number in 0..1000000");
  CHECK(error_of("grid 3\n1 1 1\n") ==
        "c.txt:2: a row of a q matrix in a file that gives a polyline (one or the other)");
  CHECK(error_of("grid 3\ngrid 4\n") == "c.txt:2: a second grid (the first is on line 1)");
  CHECK(error_of("grid 3\nsigma 0\n") == "c.txt:2: sigma must be > 0, not 0");
  CHECK(error_of("grid 3\npolyline (1,1) (2;2)\n") == "c.txt:2: bad vertex '(2;2)' (write (x,y))");
  CHECK(error_of("grid 3\nwiggle\n") ==
        "c.txt:2: unknown keyword 'wiggle' (a q matrix row, or: grid, sigma, polyline, closed)");
  CHECK(error_of("# nothing\n") ==
        "c.txt:1: no curve: give a q matrix (m rows of m numbers) or a polyline (grid, polyline "
        "lines)");
  CHECK(error_of("polyline (0,0) (1,1)\n") == "c.txt:1: a polyline needs a grid line (grid <m>)");
  // Geometry: a curve that leaves the grid, or crosses itself.
  CHECK(error_of("grid 2\npolyline (1/2,1/2) (5/2,1/2)\n").rfind("c.txt: ", 0) == 0);
  CHECK(error_of("grid 2\npolyline (0,0) (2,2) (2,0) (0,2)\n").rfind("c.txt: ", 0) == 0);
}

TEST_CASE("a round configuration written by mc::round_config_json reads back to itself") {
  const mc::RoundSystem system(mc::GridTiling(2, mc::Neighbourhood::four), {0, 1, 1, 3},
                               mc::McParams{1, mc::Rational(1, 2), mc::Rational(2, 3)});
  const mc::Counts robots{5, 0, 0, 2};
  const std::string text = mc::round_config_json(system, robots);
  std::istringstream in(text);
  const mc::RoundConfig back = mc::read_round_config(in, "written");
  CHECK(back.robots == robots);
  CHECK(back.system.q() == system.q());
  CHECK(back.system.params().rho2 == mc::Rational(2, 3));
  CHECK(back.system.grid().neighbourhood() == mc::Neighbourhood::four);
  CHECK(mc::round_config_json(back.system, back.robots) == text);
  std::istringstream bad("{\"m\": 2}");
  CHECK_THROWS_WITH(mc::read_round_config(bad, "b.json"),
                    "round config 'b.json': missing field 'nbh'");
}
