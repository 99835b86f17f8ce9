#include "models/path_reservation/scenario_file.hpp"

#include <algorithm>
#include <charconv>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "support/line_statements.hpp"
#include "support/text_file.hpp"

namespace path_reservation {

namespace {

using support::LineError;
using support::once;
using support::trim;
using support::words;

constexpr int max_side = 64;   // a plane holds at most 64 cells
constexpr int max_range = 128; // twice the longest side: beyond it every robot hears all

std::optional<int> whole(const std::string& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty())
    return std::nullopt;
  return value;
}

int whole_in(const std::string& what, const std::string& text, int lo, int hi) {
  const auto value = whole(text);
  if (!value || *value < lo || *value > hi)
    throw LineError{what + ": '" + text + "' is not a whole number in " + std::to_string(lo) +
                    ".." + std::to_string(hi)};
  return *value;
}

// One waypoint "(x,y)", spaces allowed around the numbers.
std::optional<Cell> cell(const std::string& text) {
  if (text.size() < 2 || text.front() != '(' || text.back() != ')')
    return std::nullopt;
  const std::string inside = text.substr(1, text.size() - 2);
  const auto comma = inside.find(',');
  if (comma == std::string::npos)
    return std::nullopt;
  const auto x = whole(trim(inside.substr(0, comma))), y = whole(trim(inside.substr(comma + 1)));
  if (!x || !y)
    return std::nullopt;
  return Cell{*x, *y};
}

// The waypoints of a robot line: each from '(' to ')', or else a word, which is no cell.
std::vector<Cell> waypoints(const std::string& text) {
  std::vector<Cell> out;
  std::size_t at = text.find_first_not_of(" \t");
  while (at != std::string::npos) {
    std::size_t end = text[at] == '(' ? text.find(')', at) : text.find_first_of(" \t", at);
    end = end == std::string::npos ? text.size() : end + (text[at] == '(' ? 1 : 0);
    const std::string word = text.substr(at, end - at);
    const auto waypoint = cell(word);
    if (!waypoint)
      throw LineError{"bad cell '" + word + "' (write (x,y) with whole numbers)"};
    out.push_back(*waypoint);
    at = text.find_first_not_of(" \t", end);
  }
  if (out.empty())
    throw LineError{"robot needs its waypoints, as in: robot (0,2) (3,2)"};
  return out;
}

// The statements seen so far, with the line of each one that may appear once.
struct Statements {
  Scenario scenario;
  std::optional<int> name_line, description_line, plane_line, range_line;
};

void parse_line(const std::string& keyword, const std::string& rest, int line, Statements& s) {
  if (keyword == "name" || keyword == "description") {
    once(keyword == "name" ? s.name_line : s.description_line, line, keyword);
    if (rest.empty())
      throw LineError{keyword + " needs a value"};
    (keyword == "name" ? s.scenario.name : s.scenario.description) = rest;
  } else if (keyword == "plane") {
    once(s.plane_line, line, "plane");
    const auto sides = words(rest);
    if (sides.size() != 2)
      throw LineError{"plane takes two numbers, the width and the height"};
    s.scenario.width = whole_in("plane width", sides[0], 1, max_side);
    s.scenario.height = whole_in("plane height", sides[1], 1, max_side);
  } else if (keyword == "range") {
    once(s.range_line, line, "range");
    const auto values = words(rest);
    if (values.size() != 1)
      throw LineError{"range takes one number, C"};
    s.scenario.range = whole_in("range", values[0], 1, max_range);
  } else if (keyword == "robot") {
    s.scenario.paths.push_back(waypoints(rest));
  } else {
    throw LineError{"unknown keyword '" + keyword +
                    "' (known: name, description, plane, range, robot)"};
  }
}

} // namespace

Scenario parse_scenario(std::istream& in, const std::string& source_name) {
  Statements s;
  // A missing statement is reported at the last line, where it could still have come.
  const std::string at_end =
      support::for_each_statement(in, source_name, [&s](const std::string& text, int line) {
        const auto space = text.find_first_of(" \t");
        const std::string keyword = text.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : trim(text.substr(space));
        parse_line(keyword, rest, line, s);
      });
  if (!s.plane_line)
    throw std::invalid_argument(at_end + "no plane line (plane <width> <height>)");
  if (!s.range_line)
    throw std::invalid_argument(at_end + "no range line (range <C>)");
  if (s.scenario.paths.empty())
    throw std::invalid_argument(at_end + "no robot line (robot (x,y) (x,y) ...)");
  if (!s.name_line)
    s.scenario.name = std::filesystem::path(source_name).stem().string();
  if (!s.description_line)
    s.scenario.description = "scenario file " + source_name;
  if (const auto why = check_scenario(s.scenario))
    throw std::invalid_argument(source_name + ": " + *why);
  return s.scenario;
}

Scenario read_scenario_file(const std::string& path) {
  // A scenario is a few lines: 1 MiB is far more than any, and a device or a binary file
  // is refused before parsing (support/text_file.hpp).
  std::istringstream in(support::read_text_file(path, 1 << 20));
  return parse_scenario(in, support::printable(path));
}

std::string scenario_file_text(const Scenario& s) {
  std::string description = s.description.substr(0, s.description.find('#'));
  std::string out = "# A path-reservation scenario (format: models/path_reservation/README.md, "
                    "\"Scenario files\").\n";
  out += "name " + s.name + "\n";
  if (!description.empty())
    out += "description " + description + "\n";
  out += "plane " + std::to_string(s.width) + " " + std::to_string(s.height) + "\n";
  out += "range " + std::to_string(s.range) + "\n";
  for (const auto& path : s.paths) {
    out += "robot";
    for (const Cell& c : path)
      out += " " + to_string(c);
    out += "\n";
  }
  return out;
}

} // namespace path_reservation
