#include "cli/round.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "catalogue/registry.hpp"
#include "checker/interrupt.hpp"
#include "cli/exit_status.hpp"
#include "cli/report_json.hpp"
#include "support/text_file.hpp"

namespace cli {

namespace {

using catalogue::UsageError;
using Input = nlohmann::json;

[[noreturn]] void bad(const std::string& source, const std::string& what) {
  throw UsageError("round config '" + source + "': " + what);
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

mc::Rational rational(const Input& root, const std::string& source, const char* name) {
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
    bad(source,
        std::string("field '") + name + "' = " + mc::to_string(*parsed) + " is not in (0, 1)");
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

std::string region_name(const mc::GridTiling& grid, mc::RegionId u) {
  const mc::Region r = grid.region(u);
  return fmt::format("({},{})", r.row, r.col);
}

nlohmann::ordered_json matrix_json(const mc::GridTiling& grid, const mc::Counts& counts) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int i = 0; i < grid.m(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (int j = 0; j < grid.m(); ++j)
      row.push_back(counts[grid.id(i, j)]);
    rows.push_back(std::move(row));
  }
  return rows;
}

struct Outcome {
  std::vector<mc::Counts> rounds;
  std::vector<mc::Flow> flows;
  std::optional<std::size_t> t_out, t_stab;
};

// One JSON object; each matrix on one line, so that a run reads round by round.
void print_round_json(const mc::GridTiling& grid, const Outcome& outcome) {
  auto number = [](const std::optional<std::size_t>& value) {
    return value ? std::to_string(*value) : std::string("null");
  };
  std::cout << "{\n  \"version\": \"" << tool_version() << "\",\n  \"rounds\": [";
  for (std::size_t t = 0; t < outcome.rounds.size(); ++t)
    std::cout << (t == 0 ? "\n    " : ",\n    ") << matrix_json(grid, outcome.rounds[t]).dump();
  std::cout << "\n  ],\n  \"T_out\": " << number(outcome.t_out)
            << ",\n  \"T_stab\": " << number(outcome.t_stab) << "\n}" << std::endl;
}

void print_text(const RoundConfig& config, const Outcome& outcome) {
  const mc::RoundSystem& system = config.system;
  const mc::GridTiling& grid = system.grid();
  const int m = grid.m();
  std::size_t width = 1;
  for (const auto& counts : outcome.rounds)
    for (mc::RobotCount c : counts)
      width = std::max(width, std::to_string(c).size());
  for (mc::QuantisedLength q : system.q())
    width = std::max(width, std::to_string(q).size());

  std::cout << fmt::format("{}x{} grid, {}-neighbourhood, k = {}, rho1 = {}, rho2 = {}\n", m, m,
                           static_cast<int>(grid.neighbourhood()), system.params().k,
                           mc::to_string(system.params().rho1),
                           mc::to_string(system.params().rho2));
  std::cout << "q in units of sigma (. = off the curve), row 0 at the top:\n";
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const mc::QuantisedLength q = system.q()[grid.id(i, j)];
      std::cout << fmt::format(" {:>{}}", q == 0 ? std::string(".") : std::to_string(q), width);
    }
    std::cout << '\n';
  }
  for (std::size_t t = 0; t < outcome.rounds.size(); ++t) {
    const mc::Counts& counts = outcome.rounds[t];
    std::cout << fmt::format("M{} (start of round {}, {} robots):\n", t, t, mc::total(counts));
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j)
        std::cout << fmt::format(" {:>{}}", counts[grid.id(i, j)], width);
      std::cout << '\n';
    }
    if (t < outcome.flows.size()) {
      std::string moves;
      for (const mc::Transfer& move : outcome.flows[t].transfers)
        moves += fmt::format("{}{}->{} {}", moves.empty() ? "" : ", ", region_name(grid, move.from),
                             region_name(grid, move.to), move.robots);
      std::cout << fmt::format("  round {} moves: {}\n", t, moves.empty() ? "none" : moves);
    }
  }
  if (outcome.t_out)
    std::cout << fmt::format("T_out = {}: from round {} on no robot leaves or joins a region "
                             "off the curve that has robots (Out)\n",
                             *outcome.t_out, *outcome.t_out);
  if (outcome.t_stab)
    std::cout << fmt::format("T_stab = {}: from round {} on no robot leaves or joins any "
                             "region: M{} is the fixed point\n",
                             *outcome.t_stab, *outcome.t_stab, outcome.rounds.size() - 1);
}

} // namespace

RoundConfig read_round_config(std::istream& in, const std::string& source) {
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

  const int m = static_cast<int>(whole(field(root, source, "m"), 1, max_grid_side, source, "m"));
  const Input& nbh = field(root, source, "nbh");
  if (!nbh.is_number_integer() || (nbh.get<std::int64_t>() != 4 && nbh.get<std::int64_t>() != 8))
    bad(source, "nbh must be 4 or 8, not " + nbh.dump());
  mc::McParams params;
  params.k = whole(field(root, source, "k"), 1, mc::max_robots, source, "k");
  params.rho1 = rational(root, source, "rho1");
  params.rho2 = rational(root, source, "rho2");
  std::vector<mc::QuantisedLength> q = matrix(root, source, "q", m, mc::max_quantised_length);
  mc::Counts robots = matrix(root, source, "robots", m, mc::max_robots);
  if (mc::total(robots) > mc::max_robots)
    bad(source, "more than " + std::to_string(mc::max_robots) + " robots in all");
  const auto neighbourhood =
      nbh.get<std::int64_t>() == 4 ? mc::Neighbourhood::four : mc::Neighbourhood::eight;
  try {
    return {mc::RoundSystem(mc::GridTiling(m, neighbourhood), std::move(q), params),
            std::move(robots)};
  } catch (const std::invalid_argument& e) { // not reached: everything is checked above
    bad(source, e.what());
  }
}

int command_round(const RoundRequest& request) {
  std::optional<RoundConfig> config;
  // A round configuration is a grid and counts: 16 MiB is far more than any, and a device,
  // a directory or a binary file is refused before parsing (support/text_file.hpp).
  constexpr std::size_t max_config_bytes = 16 << 20;
  std::string text;
  try {
    text = request.config == "-"
               ? support::read_text_stream(std::cin, "standard input", max_config_bytes)
               : support::read_text_file(request.config, max_config_bytes);
  } catch (const std::invalid_argument& e) {
    throw UsageError("round config: " + std::string(e.what()));
  }
  std::istringstream in(text);
  config.emplace(read_round_config(in, support::printable(request.config)));
  const mc::RoundSystem& system = config->system;

  Outcome outcome;
  if (request.to_fixpoint) {
    mc::RunOptions options;
    options.max_rounds = request.max_rounds;
    const auto began = std::chrono::steady_clock::now();
    std::string why;
    options.stop = [&] {
      if (checker::stop_requested())
        why = "interrupted";
      else if (request.max_seconds > 0 &&
               std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count() >
                   request.max_seconds)
        why = "time limit reached (--max-seconds)";
      return !why.empty();
    };
    options.stop_reason = "stopped";
    mc::FixpointRun run;
    try {
      run = system.run_to_fixpoint(config->robots, options);
    } catch (const mc::RoundLimitReached& e) {
      std::cerr << "tioa-check: incomplete: " << (why.empty() ? "" : why + ": ") << e.what()
                << (why.empty() ? " (raise --max-rounds)" : "") << std::endl;
      return some_incomplete;
    }
    outcome.rounds = std::move(run.rounds);
    outcome.flows = std::move(run.flows);
    outcome.t_out = run.t_out;
    outcome.t_stab = run.t_stab;
  } else {
    outcome.flows.push_back(system.flow(config->robots));
    outcome.rounds = {config->robots, outcome.flows.back().apply(config->robots)};
  }
  if (request.json)
    print_round_json(system.grid(), outcome);
  else
    print_text(*config, outcome);
  return all_hold;
}

Command round_command() {
  return {"round",
          "the motion-coordination algorithm at round level on one configuration (JSON): the "
          "next round's robots per region, or every round to the fixed point",
          [](CLI::App& command) -> std::function<int()> {
            auto request = std::make_shared<RoundRequest>();
            command.add_option("--config", request->config, "the configuration file ('-': stdin)")
                ->type_name("FILE")
                ->required();
            command.add_flag("--json", request->json, "print one JSON object on stdout");
            command.add_flag("--to-fixpoint", request->to_fixpoint,
                             "every round to the fixed point, with T_out and T_stab");
            command
                .add_option("--max-rounds", request->max_rounds,
                            "with --to-fixpoint: give up (exit 3) when the counts still change in "
                            "this round (default 100000)")
                ->type_name("N")
                ->check(whole_number());
            command
                .add_option("--max-seconds", request->max_seconds,
                            "with --to-fixpoint: give up (exit 3) after S seconds (0: no limit)")
                ->type_name("S")
                ->check(CLI::NonNegativeNumber);
            return [request] { return command_round(*request); };
          }};
}

} // namespace cli
