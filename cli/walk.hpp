#pragma once
// `walk`: one random execution of a model, as SPIN's and TLC's simulation modes give: from
// a start state drawn at random, each step drawn uniformly among the enabled ones (a tick
// is one of them), until the number of steps, a state with no step, or a state that breaks
// an invariant of the model (or the one given with --invariant).

#include <cstdint>
#include <string>

#include "catalogue/registry.hpp"
#include "cli/settings.hpp"

namespace cli {

struct WalkSettings {
  std::uint64_t steps = 100;
  std::uint64_t seed = 1;
  std::string from = "start"; // or "arbitrary": the start state is any valuation
};

// Exit code: 1 when the walk broke an invariant, 0 otherwise (a walk proves nothing: its
// result is reported incomplete).
int command_walk(const catalogue::Catalogue& models, const ModelRequest& request,
                 const WalkSettings& walk, const RunSettings& settings);

} // namespace cli
