#include "models/mc/round_config.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/text_file.hpp"

namespace mc {

namespace {

using Input = nlohmann::json;

[[noreturn]] void bad(const std::string& source, const std::string& what) {
  throw std::invalid_argument("round config '" + source + "': " + what);
}

const Input& field(const Input& root, const std::string& source, const char* name) {
  if (!root.contains(name))
    bad(source, std::string("missing field '") + name + "'");
  return root.at(name);
}

std::int64_t whole(const Input& value, std::int64_t lo, std::int64_t hi, const std::string& source,
                   const std::string& what) {
  if (!value.is_number_integer())
    bad(source, what + " must be a whole number, not " + value.dump());
  const bool too_big =
      value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(hi);
  if (too_big || value.get<std::int64_t>() < lo || value.get<std::int64_t>() > hi)
    bad(source, what + " = " + value.dump() + " is out of range " + std::to_string(lo) + ".." +
                    std::to_string(hi));
  return value.get<std::int64_t>();
}

Rational rational(const Input& root, const std::string& source, const char* name) {
  const Input& value = field(root, source, name);
  if (!value.is_string())
    bad(source, std::string("field '") + name +
                    "' must be a string holding an exact rational like \"9/10\", not " +
                    value.dump());
  const auto parsed = support::parse_rational(value.get<std::string>());
  if (!parsed)
    bad(source, std::string("field '") + name + "': '" + value.get<std::string>() +
                    "' is not a rational like 9/10, 1/2 or 0.9");
  if (*parsed <= 0 || *parsed >= 1)
    bad(source, std::string("field '") + name + "' = " + to_string(*parsed) + " is not in (0, 1)");
  return *parsed;
}

// An m×m matrix of whole numbers in lo..hi, row by row (region id = row·m + column).
std::vector<std::int64_t> matrix(const Input& root, const std::string& source, const char* name,
                                 int m, std::int64_t hi) {
  const Input& value = field(root, source, name);
  const std::string shape = fmt::format("an array of {} rows of {} whole numbers", m, m);
  if (!value.is_array() || value.size() != static_cast<std::size_t>(m))
    bad(source, fmt::format("field '{}' must be {} (m = {}), not {}", name, shape, m,
                            value.is_array() ? std::to_string(value.size()) + " rows"
                                             : std::string(value.type_name())));
  std::vector<std::int64_t> out;
  for (int i = 0; i < m; ++i) {
    const Input& row = value[static_cast<std::size_t>(i)];
    if (!row.is_array() || row.size() != static_cast<std::size_t>(m))
      bad(source, fmt::format("field '{}' must be {}: row {} has {}", name, shape, i,
                              row.is_array() ? std::to_string(row.size()) + " entries"
                                             : "type " + std::string(row.type_name())));
    for (int j = 0; j < m; ++j)
      out.push_back(whole(row[static_cast<std::size_t>(j)], 0, hi, source,
                          fmt::format("{}[{}][{}]", name, i, j)));
  }
  return out;
}

} // namespace

RoundConfig read_round_config(std::istream& in, const std::string& source, const CurveFile* curve) {
  Input root;
  try {
    root = Input::parse(in);
  } catch (const Input::parse_error& e) {
    bad(source, std::string("not valid JSON: ") + e.what());
  }
  if (!root.is_object())
    bad(source, std::string("the configuration must be a JSON object, not ") + root.type_name());
  static const char* const known[] = {"m", "nbh", "k", "rho1", "rho2", "q", "robots"};
  for (const auto& [key, value] : root.items())
    if (std::find_if(std::begin(known), std::end(known), [&](const char* k) { return key == k; }) ==
        std::end(known))
      bad(source, "unknown field '" + key + "' (fields: m, nbh, k, rho1, rho2, q, robots)");

  const int m = static_cast<int>(whole(field(root, source, "m"), 1, max_config_side, source, "m"));
  const Input& nbh = field(root, source, "nbh");
  if (!nbh.is_number_integer() || (nbh.get<std::int64_t>() != 4 && nbh.get<std::int64_t>() != 8))
    bad(source, "nbh must be 4 or 8, not " + nbh.dump());
  McParams params;
  params.k = whole(field(root, source, "k"), 1, max_robots, source, "k");
  params.rho1 = rational(root, source, "rho1");
  params.rho2 = rational(root, source, "rho2");
  std::vector<QuantisedLength> q;
  if (curve) { // the curve file's q, in place of the field (which may be left out)
    if (curve->m != m)
      bad(source, "the curve file's grid is " + std::to_string(curve->m) + "x" +
                      std::to_string(curve->m) + ", the configuration's m = " + std::to_string(m));
    q.assign(curve->q.begin(), curve->q.end());
  } else {
    q = matrix(root, source, "q", m, max_quantised_length);
  }
  Counts robots = matrix(root, source, "robots", m, max_robots);
  if (total(robots) > max_robots)
    bad(source, "more than " + std::to_string(max_robots) + " robots in all");
  const auto neighbourhood =
      nbh.get<std::int64_t>() == 4 ? Neighbourhood::four : Neighbourhood::eight;
  try {
    return {RoundSystem(GridTiling(m, neighbourhood), std::move(q), params), std::move(robots)};
  } catch (const std::invalid_argument& e) { // not reached: everything is checked above
    bad(source, e.what());
  }
}

RoundConfig read_round_config_file(const std::string& path, const CurveFile* curve) {
  // A round configuration is a grid and counts: 16 MiB is far more than any, and a device,
  // a directory or a binary file is refused before parsing (support/text_file.hpp).
  constexpr std::size_t max_config_bytes = 16 << 20;
  std::string text;
  try {
    text = support::read_text_file(path, max_config_bytes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("round config: " + std::string(e.what()));
  }
  std::istringstream in(text);
  return read_round_config(in, support::printable(path), curve);
}

std::string round_config_json(const RoundSystem& system, const Counts& robots) {
  const GridTiling& grid = system.grid();
  const auto matrix = [&](const std::vector<std::int64_t>& values) {
    std::string out = "[";
    for (int i = 0; i < grid.m(); ++i) {
      out += i == 0 ? "\n    [" : ",\n    [";
      for (int j = 0; j < grid.m(); ++j)
        out += (j ? ", " : "") + std::to_string(values[grid.id(i, j)]);
      out += "]";
    }
    return out + "]";
  };
  return fmt::format("{{\n  \"m\": {},\n  \"nbh\": {},\n  \"k\": {},\n  \"rho1\": \"{}\",\n"
                     "  \"rho2\": \"{}\",\n  \"q\": {},\n  \"robots\": {}\n}}\n",
                     grid.m(), static_cast<int>(grid.neighbourhood()), system.params().k,
                     to_string(system.params().rho1), to_string(system.params().rho2),
                     matrix(system.q()), matrix(robots));
}

} // namespace mc
