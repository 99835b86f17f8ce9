#include "proofs/vlayer_mc/symbolic_starts.hpp"

#include <algorithm>
#include <chrono>

namespace vlayer_mc {

SymbolicRun stabilise_from_u(const VlConfig& config, const ArbitraryStarts& starts,
                             const tioa::Automaton& layer,
                             const std::vector<tioa::StatePredicate>& legal,
                             std::uint64_t witness_after, const checker::Limits& limits) {
  namespace sym = checker::symbolic;
  const auto began = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  };
  const tioa::Automaton env = u_environment(config, starts);
  const sym::BddSession session(std::max(layer.layout().bits(), env.layout().bits()));
  SymbolicRun run;
  sym::LearningFigures figures;
  // R(env): every state the environment reaches with its inputs from the nodes free.
  const auto stop = [&] { return limits.out_of_time(elapsed()); };
  const sym::Space env_space(env);
  sym::System env_system(env_space, figures);
  env_system.set_stop(stop);
  bdd env_reach;
  try {
    env_reach = env_system.reach(sym::start_states(env_space, env.start()));
  } catch (const sym::Stopped&) {
    run.result.stopped = true;
    return run;
  }
  run.environment_states = env_space.count(env_reach);

  const sym::Space space(layer);
  sym::BddSession::reorder_by_variables(layer.layout());
  sym::System system(space, figures);
  system.set_stop(stop);
  // Every valuation of the nodes' variables, with the environment in R(env).
  const bdd start = sym::move_set(env_reach, env_space, space) & space.valid();
  bdd in_legal = space.valid();
  for (const tioa::StatePredicate& conjunct : legal)
    in_legal &= sym::learn_predicate(space, conjunct, figures);
  run.result = sym::stabilise(system, start, in_legal, witness_after);
  run.learned_cubes = figures.leaves;
  run.seconds = elapsed();
  return run;
}

} // namespace vlayer_mc
