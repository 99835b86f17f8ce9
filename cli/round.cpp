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

void print_text(const mc::RoundConfig& config, const Outcome& outcome) {
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

int command_round(const RoundRequest& request) {
  std::optional<mc::RoundConfig> config;
  std::optional<mc::CurveFile> curve;
  try {
    if (!request.curve_file.empty())
      curve.emplace(mc::read_curve_file(request.curve_file));
    const mc::CurveFile* given = curve ? &*curve : nullptr;
    if (request.config == "-") {
      // A round configuration is a grid and counts: 16 MiB is far more than any.
      std::istringstream in(
          support::read_text_stream(std::cin, "standard input", std::size_t{16} << 20));
      config.emplace(mc::read_round_config(in, "-", given));
    } else {
      config.emplace(mc::read_round_config_file(request.config, given));
    }
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
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
            command
                .add_option("--curve-file", request->curve_file,
                            "a curve file (a q matrix or a polyline, models/mc/README.md) whose q "
                            "replaces the configuration's, which may then leave q out")
                ->type_name("FILE");
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
