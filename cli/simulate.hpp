#pragma once
// `tioa-check simulate`: the Matlab simulation of seed 002 §VII at round level
// (models/mc/simulation.hpp): T_out and T_stab for a range of m and the curves C1–C3, the
// paper's claim about C2, and with --out the CSV and the figures 8 and 9 as SVG.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/app.hpp"

namespace cli {

struct SimulateRequest {
  std::string out; // a directory; empty: write no files
  int m_from = 10;
  int m_to = 20;
  std::vector<std::string> curves{"C1", "C2", "C3"};
  std::int64_t robots = 100'000;
  std::int64_t e = 5;
  std::string rho2 = "9/10";
  std::string sigma = "1/4";
  // The sizes of C1–C3 (models/mc/curve_simulation.hpp): our choice, the paper gives none.
  std::vector<std::string> rect_size{"1/3", "1/3"};  // C1, C2: width, height as fractions of m
  std::string rect_inset = "1/2";                    // C1, C2: from the corner, units of b
  std::vector<std::string> ring_radii{"1/8", "1/4"}; // C3: inner, outer as fractions of m b
  int nbh = 4;
  std::optional<int> fig8_m; // default: 10 when in the range, else m_from
  std::string dominance = "9/10";
  std::int64_t max_rounds = 100'000;
  bool json = false;
};

// Declares the options of the subcommand `command` into `request`.
void add_simulate_options(CLI::App& command, SimulateRequest& request);

// Exit codes: 0 done (the claim holds, or C2 is not in the sweep); 1 the claim about C2 does
// not hold; 3 a run did not reach its fixed point within --max-rounds (one line on stderr).
// Throws catalogue::UsageError on bad values (one line).
int command_simulate(const SimulateRequest& request);

// The command `simulate` for cli::run: its options, then command_simulate.
Command simulate_command();

} // namespace cli
