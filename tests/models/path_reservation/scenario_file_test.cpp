// Scenario files of the path-reservation model (models/path_reservation/scenario_file.hpp):
// the example file equals the built-in scenario, defaults, and one line for every error.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "models/path_reservation/scenario_file.hpp"

using path_reservation::parse_scenario;
using path_reservation::read_scenario_file;
using path_reservation::Scenario;

namespace {

const std::string source = "dir/test.txt";

Scenario parse(const std::string& text) {
  std::istringstream in(text);
  return parse_scenario(in, source);
}

// The message of the std::invalid_argument that parsing throws, or a marker when none.
std::string parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<no error>";
}

// The top of the source tree (tests/CMakeLists.txt defines it: __FILE__ may be relative).
std::filesystem::path repository() {
  return TIOA_SOURCE_DIR;
}

} // namespace

TEST_CASE("scenario file: the example crossing.txt is the built-in crossing",
          "[scenario-file][path-reservation]") {
  const auto path = repository() / "models/path_reservation/scenarios/crossing.txt";
  const Scenario read = read_scenario_file(path.string());
  const Scenario& built_in = path_reservation::find_scenario("crossing");
  CHECK(read.name == built_in.name);
  CHECK(read.description == built_in.description);
  CHECK(read.width == built_in.width);
  CHECK(read.height == built_in.height);
  CHECK(read.range == built_in.range);
  CHECK(read.paths == built_in.paths);
}

TEST_CASE("scenario file: the name and description default to the file's",
          "[scenario-file][path-reservation]") {
  const Scenario s = parse("plane 5 1\nrange 5\nrobot (0,0) (2,0) (4,0)\n");
  CHECK(s.name == "test");
  CHECK(s.description == "scenario file dir/test.txt");
  CHECK(s.width == 5);
  CHECK(s.height == 1);
  CHECK(s.range == 5);
  REQUIRE(s.robots() == 1);
  CHECK(s.chunks(0) == 2);
}

TEST_CASE("scenario file: comments, blank lines, tabs, CRLF and spaces in cells are allowed",
          "[scenario-file][path-reservation]") {
  const Scenario s = parse("# a comment\n\n  \t\nname  two words \r\nplane\t4 4 # a comment\r\n"
                           "range 6\nrobot ( 0 , 2 )(3,2)\nrobot (2,0)   (2,3)#\n");
  CHECK(s.name == "two words");
  CHECK(s.paths == path_reservation::find_scenario("crossing").paths);
}

TEST_CASE("scenario file: every error is one line naming the file and the line",
          "[scenario-file][path-reservation]") {
  const std::string plane = "plane 4 4\n", range = "range 6\n", robot = "robot (0,2) (3,2)\n";
  SECTION("unknown keyword") {
    CHECK(parse_error(plane + "robots (0,2) (3,2)\n") ==
          "dir/test.txt:2: unknown keyword 'robots' (known: name, description, plane, range, "
          "robot)");
  }
  SECTION("bad number") {
    CHECK(parse_error("plane 4 x\n") ==
          "dir/test.txt:1: plane height: 'x' is not a whole number in 1..64");
    CHECK(parse_error("plane 65 1\n") ==
          "dir/test.txt:1: plane width: '65' is not a whole number in 1..64");
    CHECK(parse_error(plane + "range 6.5\n") ==
          "dir/test.txt:2: range: '6.5' is not a whole number in 1..128");
    CHECK(parse_error(plane + "range 0\n") ==
          "dir/test.txt:2: range: '0' is not a whole number in 1..128");
    CHECK(parse_error(plane + "range 99999999999\n") ==
          "dir/test.txt:2: range: '99999999999' is not a whole number in 1..128");
    CHECK(parse_error("plane 4\n") ==
          "dir/test.txt:1: plane takes two numbers, the width and the height");
    CHECK(parse_error(plane + "range 6 7\n") == "dir/test.txt:2: range takes one number, C");
  }
  SECTION("bad cell syntax") {
    CHECK(parse_error(plane + range + "robot (0;2) (3,2)\n") ==
          "dir/test.txt:3: bad cell '(0;2)' (write (x,y) with whole numbers)");
    CHECK(parse_error(plane + range + "robot (0,2) 3,2\n") ==
          "dir/test.txt:3: bad cell '3,2' (write (x,y) with whole numbers)");
    CHECK(parse_error(plane + range + "robot (0,2) (3,x)\n") ==
          "dir/test.txt:3: bad cell '(3,x)' (write (x,y) with whole numbers)");
    CHECK(parse_error(plane + range + "robot (0,2) (3,2\n") ==
          "dir/test.txt:3: bad cell '(3,2' (write (x,y) with whole numbers)");
    CHECK(parse_error(plane + range + "robot\n") ==
          "dir/test.txt:3: robot needs its waypoints, as in: robot (0,2) (3,2)");
  }
  SECTION("missing plane, range or robot: at the last line") {
    CHECK(parse_error(range + robot) == "dir/test.txt:2: no plane line (plane <width> <height>)");
    CHECK(parse_error(plane + robot + "\n# the end\n") ==
          "dir/test.txt:4: no range line (range <C>)");
    CHECK(parse_error(plane + range) == "dir/test.txt:2: no robot line (robot (x,y) (x,y) ...)");
    CHECK(parse_error("") == "dir/test.txt:1: no plane line (plane <width> <height>)");
  }
  SECTION("duplicate plane, range, name or description") {
    CHECK(parse_error(plane + range + plane) ==
          "dir/test.txt:3: a second plane (the first is on line 1)");
    CHECK(parse_error(plane + range + robot + range) ==
          "dir/test.txt:4: a second range (the first is on line 2)");
    CHECK(parse_error("name a\nname b\n") ==
          "dir/test.txt:2: a second name (the first is on line 1)");
    CHECK(parse_error("description\n") == "dir/test.txt:1: description needs a value");
  }
  SECTION("file cannot be opened") {
    const std::string missing = "no/such/scenario.txt";
    try {
      read_scenario_file(missing);
      FAIL("no error");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()) == "no/such/scenario.txt: No such file or directory");
    }
    CHECK_THROWS_WITH(read_scenario_file(std::filesystem::temp_directory_path().string()),
                      std::filesystem::temp_directory_path().string() +
                          ": is a directory, not a file");
    CHECK_THROWS_WITH(read_scenario_file("/dev/zero"), "/dev/zero: not a regular file");
  }
}

TEST_CASE("scenario file: a scenario that check_scenario refuses gives its reason",
          "[scenario-file][path-reservation]") {
  // Each file, and the same scenario built by hand, whose reason the file's error repeats.
  const std::vector<std::pair<std::string, Scenario>> refused{
      // Definition 4: the chunk (0,0)-(3,0) leaves Cir((0,0), C/2) when C = 4.
      {"plane 4 1\nrange 4\nrobot (0,0) (3,0)\n", {"", "", 4, 1, 4, {{{0, 0}, {3, 0}}}}},
      {"plane 4 4\nrange 6\nrobot (0,0) (1,2)\n", {"", "", 4, 4, 6, {{{0, 0}, {1, 2}}}}},
      {"plane 4 4\nrange 6\nrobot (0,0) (1,0)\nrobot (0,0) (0,1)\n",
       {"", "", 4, 4, 6, {{{0, 0}, {1, 0}}, {{0, 0}, {0, 1}}}}},
      {"plane 9 9\nrange 6\nrobot (0,0) (1,0)\n", {"", "", 9, 9, 6, {{{0, 0}, {1, 0}}}}},
      {"plane 2 2\nrange 3\nrobot (0,0)\n", {"", "", 2, 2, 3, {{{0, 0}}}}},
      // A waypoint off the plane, far or negative (UBSan once saw the shift of its bit).
      {"plane 4 4\nrange 6\nrobot (0,0) (0,9)\n", {"", "", 4, 4, 6, {{{0, 0}, {0, 9}}}}},
      {"plane 4 4\nrange 6\nrobot (1,0) (-1,0)\n", {"", "", 4, 4, 6, {{{1, 0}, {-1, 0}}}}}};
  for (const auto& [text, scenario] : refused) {
    INFO(text);
    const auto reason = path_reservation::check_scenario(scenario);
    REQUIRE(reason);
    CHECK(parse_error(text) == "dir/test.txt: " + *reason);
  }
  CHECK(parse_error(refused[5].first) == "dir/test.txt: R1's waypoint (0,9) is outside the plane");
  CHECK_THAT(parse_error(refused[0].first),
             Catch::StartsWith("dir/test.txt: R1's chunk (0,0)-(3,0) leaves ") &&
                 Catch::EndsWith("(Definition 4)"));
}

TEST_CASE("scenario file: read from disk, the name is the file's stem",
          "[scenario-file][path-reservation]") {
  const auto path = std::filesystem::temp_directory_path() / "tioa-scenario-file-test.txt";
  {
    std::ofstream out(path);
    out << "plane 2 2\nrange 3\nrobot (0,0) (1,0)\nrobot (1,1) (0,1)\n";
  }
  const Scenario s = read_scenario_file(path.string());
  std::filesystem::remove(path);
  CHECK(s.name == "tioa-scenario-file-test");
  CHECK(s.description == "scenario file " + path.string());
  CHECK(s.robots() == 2);
}
