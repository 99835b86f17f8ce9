#pragma once
// `tioa-check round`: one configuration of the motion-coordination algorithm at round
// level (models/mc/round.hpp): the next round's counts per region, or with --to-fixpoint
// every round to the fixed point with T_out and T_stab.

#include <cstddef>
#include <string>

#include "cli/app.hpp"
#include "models/mc/round_config.hpp"

namespace cli {

// The largest grid side m that `round` and `simulate` accept (models/mc/round_config.hpp).
constexpr int max_grid_side = mc::max_config_side;

struct RoundRequest {
  std::string config;     // a file, or "-" for stdin
  std::string curve_file; // empty, or a curve file whose q replaces the config's
                          // (models/mc/curve_file.hpp)
  bool json = false;
  bool to_fixpoint = false;
  std::size_t max_rounds = 100'000;
  double max_seconds = 0; // --to-fixpoint: give up after this long (0: never)
};

// Exit codes: 0 done; 3 no fixed point within max_rounds (one line on stderr). Throws
// catalogue::UsageError on a bad configuration.
int command_round(const RoundRequest& request);

// The command `round` for cli::run: its options, then command_round.
Command round_command();

} // namespace cli
