#include "proofs/vlayer_mc/symbolic_starts.hpp"

#include <algorithm>

#include "checker/interrupt.hpp"
#include "checker/memory_budget.hpp"
#include "checker/symbolic_apart.hpp"

#include "models/vlayer_mc/junk.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "proofs/vlayer_mc/symbolic_lmc.hpp"

namespace vlayer_mc {

namespace sym = checker::symbolic;

namespace {

// The states of `space` whose junk slots are all empty, each field of each slot 0: the
// variables the slots are made of, named `VBcast.junk_kind[i]`, `CN_p.delay.junk_value[j]`
// and so on (models/vlayer_mc/vbcast.cpp, vbdelay.cpp), hold 0, junk::empty for a slot's
// kind. That is how a slot is left when it empties (and how it starts), so these are
// exactly the start states of the same instance with `junk=0`, and with the junk variables
// constant the sets are that instance's (an empty slot with its other fields free would be
// the same behaviour with more states).
bdd junk_slots_empty(const sym::Space& space) {
  static_assert(junk::empty == 0);
  bdd empty = bddtrue;
  for (const auto& v : space.variables()) {
    if (v.name.find(".junk_") == std::string::npos)
      continue;
    const tioa::VariableInfo& info = *space.automaton().layout().find(v.name);
    const auto code = static_cast<std::uint64_t>(-info.lo);
    for (std::uint32_t b = 0; b < v.width; ++b)
      empty &= ((code >> b) & 1) ? sym::Space::current(v.offset + b)
                                 : !sym::Space::current(v.offset + b);
  }
  return empty;
}

} // namespace

SymbolicU::SymbolicU(const VlConfig& config, const ArbitraryStarts& starts,
                     const tioa::Automaton& layer, const checker::ExploreOptions& options)
    : began_(std::chrono::steady_clock::now()), limits_(options.limits),
      progress_(options.progress,
                (options.task.empty() ? "symbolic" : options.task) + " (every start state)"),
      environment_(u_environment(config, starts)),
      session_(std::make_unique<sym::BddSession>(
          std::max(layer.layout().bits(), environment_.layout().bits()))) {
  const auto stop = [this] { return should_stop(); };
  const auto report = [this](const std::string& status) { progress_.show(part_ + status); };
  // R(env): every state the environment reaches with its inputs from the nodes free.
  bdd env_reach;
  {
    const sym::Space env_space(environment_);
    try {
      sym::System env_system(env_space, figures_, stop, report);
      env_system.set_stage("R(env)");
      env_reach = env_system.reach(sym::start_states(env_space, environment_.start()));
    } catch (const sym::Stopped&) {
      return;
    }
    environment_states_ = env_space.count(env_reach);
    space_.emplace(layer);
    // Every valuation of the nodes' variables, with the environment in R(env).
    start_ = sym::move_set(env_reach, env_space, *space_) & space_->valid();
    without_junk_ = start_ & junk_slots_empty(*space_);
  }
  env_reach = bddfalse;
  sym::BddSession::reorder_by_variables(layer.layout());
  try {
    system_.emplace(*space_, figures_, stop, report);
  } catch (const sym::Stopped&) {
    return; // stopped while learning the steps
  }
}

bool SymbolicU::should_stop() {
  if (checker::interrupted())
    stopped_by_ = "an interrupt (SIGINT or SIGTERM)";
  else if (limits_.out_of_time(elapsed()))
    stopped_by_ = "the time limit";
  else if (checker::resident_over_limit(limits_))
    stopped_by_ = "the memory limit";
  return !stopped_by_.empty();
}

double SymbolicU::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
}

bdd SymbolicU::conjunction(const std::vector<tioa::StatePredicate>& conjuncts) {
  if (stopped())
    return bddfalse;
  bdd set = space_->valid();
  for (const tioa::StatePredicate& conjunct : conjuncts)
    set &= sym::learn_predicate(*space_, conjunct, figures_);
  return set;
}

bdd SymbolicU::measured_lmc(const VlConfig& config, const tioa::Automaton& layer, MWindow window,
                            const KnownLmc& known) {
  if (stopped())
    return bddfalse;
  return conjunction(reset_mc_or_targetless_conjuncts(config, layer, window)) |
         known_lmc_set(*space_, known, figures_);
}

SymbolicRun SymbolicU::stabilise(const bdd& start, const bdd& legal, const bdd& settled,
                                 std::uint64_t witness_after, const std::string& part, bool apart) {
  part_ = part.empty() ? "" : part + ": ";
  SymbolicRun run;
  run.seconds = elapsed();
  run.stopped_by = stopped_by_;
  if (stopped()) {
    run.result.stopped = true;
    return run;
  }
  system_->set_settled(settled);
  run.result = apart ? sym::stabilise_apart(*system_, start, legal, witness_after,
                                            [this] { return should_stop(); })
                     : sym::stabilise(*system_, start, legal, witness_after);
  system_->set_settled(bddfalse);
  // A child that stopped itself before the parent asked: by the time limit or an interrupt,
  // which the parent sees too, or else by its own memory.
  if (run.result.stopped && stopped_by_.empty() && !should_stop())
    stopped_by_ = "the memory limit";
  run.environment_states = environment_states_;
  run.learned_cubes = figures_.leaves;
  run.seconds = elapsed();
  run.stopped_by = stopped_by_;
  return run;
}

} // namespace vlayer_mc
