#pragma once
// `tioa-check round`: one configuration of the motion-coordination algorithm at round
// level (models/mc/round.hpp): the next round's counts per region, or with --to-fixpoint
// every round to the fixed point with T_out and T_stab.

#include <cstddef>
#include <istream>
#include <string>

#include "cli/app.hpp"
#include "models/mc/round.hpp"

namespace cli {

// The largest grid side m that `round` and `simulate` accept: the grid keeps m⁴ distances;
// the paper's runs use m <= 20.
constexpr int max_grid_side = 50;

struct RoundRequest {
  std::string config; // a file, or "-" for stdin
  bool json = false;
  bool to_fixpoint = false;
  std::size_t max_rounds = 100'000;
  double max_seconds = 0; // --to-fixpoint: give up after this long (0: never)
};

// A configuration file: {"m", "nbh", "k", "rho1", "rho2", "q", "robots"} (README of
// models/mc). q[i][j], robots[i][j]: region row i (row 0 at the top), column j.
struct RoundConfig {
  mc::RoundSystem system;
  mc::Counts robots;
};

// Throws catalogue::UsageError (one line, naming `source` and the field) on anything wrong.
RoundConfig read_round_config(std::istream& in, const std::string& source);

// Exit codes: 0 done; 3 no fixed point within max_rounds (one line on stderr). Throws
// catalogue::UsageError on a bad configuration.
int command_round(const RoundRequest& request);

// The command `round` for cli::run: its options, then command_round.
Command round_command();

} // namespace cli
