// The picture of a path-reservation state in HTML reports (catalogue/path_reservation_picture):
// drawn scenarios are drawn again from their seed, and every message of a channel is listed.
#include <catch2/catch.hpp>

#include <sstream>

#include <nlohmann/json.hpp>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"

TEST_CASE("path-reservation: the picture of a drawn scenario lists every message in flight",
          "[path-reservation][picture]") {
  const auto& definition = catalogue::builtin_models().find("path-reservation");
  REQUIRE(definition.picture);
  const catalogue::Json params = {{"scenario", "random"}, {"scenario_file", ""}, {"seed", 1},
                                  {"robots", 3},          {"chunks", 2},         {"plane", 4}};
  catalogue::Json state = {{"phase[1]", "negotiating"},
                           {"chunk[1]", 0},
                           {"phase[2]", "idle"},
                           {"chunk[2]", 0},
                           {"phase[3]", "released"},
                           {"chunk[3]", 0},
                           {"net[1][2][0].kind", "request"},
                           {"net[1][2][0].round", 0},
                           {"net[1][2][1].kind", "release"},
                           {"net[1][2][1].round", 0},
                           {"net[1][2][2].kind", "none"},
                           {"net.overflow", false}};
  std::ostringstream out;
  definition.picture(out, params, state, "t");
  const std::string page = out.str();
  CHECK(page.find("no picture") == std::string::npos);
  CHECK(page.find("<svg") != std::string::npos);
  CHECK(page.find("request R1 → R2 (zone of chunk 0)") != std::string::npos);
  CHECK(page.find("release R1 → R2 (zone of chunk 0)") != std::string::npos);
  state["net.overflow"] = true;
  std::ostringstream full;
  definition.picture(full, params, state, "u");
  CHECK(full.str().find("its channel full") != std::string::npos);
}
