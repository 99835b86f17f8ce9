#include "models/mc/curve_file.hpp"

#include <cctype>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "models/mc/assign.hpp"
#include "models/mc/curve_local.hpp"
#include "models/mc/grid.hpp"
#include "support/line_statements.hpp"
#include "support/text.hpp"
#include "support/text_file.hpp"

namespace mc {

namespace {

using support::LineError;
using support::once;
using support::trim;
using support::words;

std::int64_t whole_in(const std::string& what, const std::string& text, std::int64_t lo,
                      std::int64_t hi) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < lo ||
      value > hi)
    throw LineError{what + ": '" + support::printable(text) + "' is not a whole number in " +
                    std::to_string(lo) + ".." + std::to_string(hi)};
  return value;
}

Rational rational(const std::string& what, const std::string& text) {
  const auto value = support::parse_rational(text);
  if (!value)
    throw LineError{what + ": '" + support::printable(text) +
                    "' is not an exact number like 3, 1/2 or 0.25"};
  return *value;
}

// The vertices of a polyline line: each "(x,y)" with x and y exact rationals.
std::vector<RationalPoint> points(const std::string& text) {
  std::vector<RationalPoint> out;
  std::size_t at = text.find_first_not_of(" \t");
  while (at != std::string::npos) {
    if (text[at] != '(')
      throw LineError{"bad vertex '" + support::printable(text.substr(at)) +
                      "' (write (x,y) with exact numbers, as in (1/2,3))"};
    const std::size_t close = text.find(')', at);
    if (close == std::string::npos)
      throw LineError{"a vertex misses its ')'"};
    const std::string inside = text.substr(at + 1, close - at - 1);
    const std::size_t comma = inside.find(',');
    if (comma == std::string::npos)
      throw LineError{"bad vertex '(" + support::printable(inside) + ")' (write (x,y))"};
    out.push_back({rational("x", trim(inside.substr(0, comma))),
                   rational("y", trim(inside.substr(comma + 1)))});
    at = text.find_first_not_of(" \t", close + 1);
  }
  if (out.empty())
    throw LineError{"polyline needs vertices, as in: polyline (1/2,1/2) (5/2,1/2)"};
  return out;
}

// The statements seen so far, with the line of each.
struct Statements {
  std::vector<std::vector<std::int64_t>> rows; // the q matrix
  int first_row_line = 0;
  std::optional<int> grid_line, sigma_line, closed_line, polyline_line;
  int m = 0;
  Rational sigma = 1;
  std::vector<RationalPoint> vertices;
};

bool matrix_entry(const std::string& word) {
  return word == "." ||
         (!word.empty() && (std::isdigit(static_cast<unsigned char>(word[0])) || word[0] == '-'));
}

void parse_line(const std::string& text, int line, Statements& s) {
  const auto parts = words(text);
  const std::string& keyword = parts.front();
  if (matrix_entry(keyword)) {
    if (s.polyline_line || s.grid_line)
      throw LineError{"a row of a q matrix in a file that gives a polyline (one or the other)"};
    if (s.rows.empty())
      s.first_row_line = line;
    std::vector<std::int64_t> row;
    for (const std::string& word : parts)
      row.push_back(word == "."
                        ? 0
                        : whole_in("q", word, 0, static_cast<std::int64_t>(max_quantised_length)));
    if (!s.rows.empty() && row.size() != s.rows.front().size())
      throw LineError{"this row has " + std::to_string(row.size()) +
                      " entries, the first row (line " + std::to_string(s.first_row_line) + ") " +
                      std::to_string(s.rows.front().size())};
    s.rows.push_back(std::move(row));
    return;
  }
  if (!s.rows.empty())
    throw LineError{"'" + support::printable(keyword) +
                    "' in a file that gives a q matrix (one or the other)"};
  const std::string rest = trim(text.substr(keyword.size()));
  if (keyword == "grid") {
    once(s.grid_line, line, "grid");
    if (parts.size() != 2)
      throw LineError{"grid takes one number, the side m"};
    s.m = static_cast<int>(whole_in("grid", parts[1], 1, max_curve_file_side));
  } else if (keyword == "sigma") {
    once(s.sigma_line, line, "sigma");
    if (parts.size() != 2)
      throw LineError{"sigma takes one number"};
    s.sigma = rational("sigma", parts[1]);
    if (s.sigma <= 0)
      throw LineError{"sigma must be > 0, not " + to_string(s.sigma)};
  } else if (keyword == "polyline") {
    if (!s.polyline_line)
      s.polyline_line = line;
    for (RationalPoint& p : points(rest))
      s.vertices.push_back(std::move(p));
  } else if (keyword == "closed") {
    once(s.closed_line, line, "closed");
    if (parts.size() != 1)
      throw LineError{"closed takes nothing"};
  } else {
    throw LineError{"unknown keyword '" + support::printable(keyword) +
                    "' (a q matrix row, or: grid, sigma, polyline, closed)"};
  }
}

} // namespace

CurveFile parse_curve_file(std::istream& in, const std::string& source) {
  Statements s;
  const std::string at_end = support::for_each_statement(
      in, source, [&s](const std::string& text, int line) { parse_line(text, line, s); });
  CurveFile out;
  if (!s.rows.empty()) {
    out.m = static_cast<int>(s.rows.size());
    if (s.rows.front().size() != s.rows.size())
      throw std::invalid_argument(at_end + "the q matrix has " + std::to_string(s.rows.size()) +
                                  " rows of " + std::to_string(s.rows.front().size()) +
                                  " entries: it must be square (m rows of m)");
    if (out.m > max_curve_file_side)
      throw std::invalid_argument(at_end + "the q matrix is larger than " +
                                  std::to_string(max_curve_file_side) + " x " +
                                  std::to_string(max_curve_file_side));
    for (const auto& row : s.rows)
      out.q.insert(out.q.end(), row.begin(), row.end());
    return out;
  }
  if (!s.polyline_line)
    throw std::invalid_argument(at_end + "no curve: give a q matrix (m rows of m numbers) or a "
                                         "polyline (grid, polyline lines)");
  if (!s.grid_line)
    throw std::invalid_argument(at_end + "a polyline needs a grid line (grid <m>)");
  out.m = s.m;
  out.sigma = s.sigma;
  try {
    out.polyline = Curve::polyline(std::move(s.vertices), s.closed_line.has_value());
    const CurveOnGrid on_grid(*out.polyline, GridTiling(s.m, Neighbourhood::four), s.sigma);
    out.q.assign(on_grid.q().begin(), on_grid.q().end());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  } catch (const PrecisionError& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
  for (std::int64_t q : out.q)
    if (q > max_quantised_length)
      throw std::invalid_argument(source + ": a region holds " + std::to_string(q) +
                                  " quanta of the curve, more than " +
                                  std::to_string(max_quantised_length) + "; choose a larger sigma");
  return out;
}

CurveFile read_curve_file(const std::string& path) {
  // A curve is a few lines: 1 MiB is far more than any (support/text_file.hpp).
  std::string text;
  try {
    text = support::read_text_file(path, 1 << 20);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("curve file: " + std::string(e.what()));
  }
  std::istringstream in(text);
  return parse_curve_file(in, support::printable(path));
}

} // namespace mc
