#include "checker/symbolic_system.hpp"

#include <cstdio>

#include "checker/symbolic_acyclic.hpp"
#include "tioa/action_footprints.hpp"

namespace checker::symbolic {

namespace {

std::vector<StepRelation> learn_actions(const Space& space, LearningFigures& figures,
                                        const LearningWatch& watch) {
  std::vector<tioa::ActionFootprint> footprints = tioa::action_footprints(space.automaton());
  std::vector<StepRelation> actions;
  for (std::size_t a = 0; a < footprints.size(); ++a)
    actions.push_back(learn_action(space, a, std::move(footprints[a].writes), figures, watch));
  return actions;
}

// What learning tells: the stop asked (Stopped), and the group and cubes reported.
LearningWatch watch_learning(const std::function<bool()>& stop,
                             const std::function<void(const std::string&)>& report) {
  if (!stop && !report)
    return {};
  return [stop, report](const std::string& group, std::uint64_t cubes) {
    if (stop && stop())
      throw Stopped{};
    if (report)
      report("learning " + group + ", " + std::to_string(cubes) + " cubes");
  };
}

} // namespace

System::System(const Space& space, LearningFigures& figures, std::function<bool()> stop,
               std::function<void(const std::string&)> report)
    : space_(&space), zero_time_(learn_actions(space, figures, watch_learning(stop, report))),
      tick_(learn_tick(space, figures, watch_learning(stop, report))), stop_(std::move(stop)),
      report_(std::move(report)) {}

void System::next_group(const char* fixpoint, std::uint32_t round, const std::string& group) const {
  if (stop_ && stop_())
    throw Stopped{};
  if (!report_)
    return;
  char nodes[32];
  std::snprintf(nodes, sizeof nodes, "%.1f M", static_cast<double>(bdd_getnodenum()) / 1e6);
  report_((stage_.empty() ? "" : stage_ + ": ") + fixpoint + ", round " + std::to_string(round) +
          (group.empty() ? "" : ", " + group) + ", " + nodes + " BDD nodes");
}

// Chained over the groups, each applied to the states not yet expanded (the frontier), which
// grows as the groups before it add states: a group's images reach the next group at once.
// Settled states take no step: they are never a step's source (their own tick leads back to
// them, nothing new).
bdd System::closure(const bdd& set, bool with_tick, bool backward, const bdd& within,
                    const bdd& goal) const {
  const char* name = backward ? (with_tick ? "back reach" : "back zero-time closure")
                              : (with_tick ? "reach" : "zero-time closure");
  std::uint32_t round = 0;
  bdd all = set, frontier = set;
  const bool stop_at_goal = goal != bddfalse;
  if (stop_at_goal && (set & goal) != bddfalse)
    return set & goal;
  const bdd moving = within & !settled_;
  const auto apply = [&](const StepRelation& step) {
    next_group(name, round, step.name());
    const bdd fresh = backward ? step.preimage(frontier) & moving & !all
                               : step.image(frontier & !settled_) & within & !all;
    all |= fresh;
    frontier |= fresh;
    return fresh;
  };
  while (frontier != bddfalse) {
    next_group(name, ++round, "");
    bdd added = bddfalse;
    for (const StepRelation& step : zero_time_)
      added |= apply(step);
    if (with_tick)
      added |= apply(tick_);
    frontier = added;
    if (stop_at_goal && (added & goal) != bddfalse)
      return added & goal;
  }
  return stop_at_goal ? bdd(bddfalse) : all;
}

bool System::stays_within(const bdd& set, const bdd& inside) const {
  if ((set & !inside) != bddfalse)
    return false;
  bdd all = set, frontier = set;
  bool left = false;
  std::uint32_t round = 0;
  const auto apply = [&](const StepRelation& step) {
    if (left)
      return bdd(bddfalse);
    next_group("staying inside", round, step.name());
    const bdd image = step.image(frontier & !settled_);
    left = (image & !inside) != bddfalse;
    const bdd fresh = image & !all;
    all |= fresh;
    frontier |= fresh;
    return fresh;
  };
  while (frontier != bddfalse && !left) {
    next_group("staying inside", ++round, "");
    bdd added = bddfalse;
    for (const StepRelation& step : zero_time_)
      added |= apply(step);
    added |= apply(tick_);
    frontier = added;
  }
  return !left;
}

bdd System::zero_time_closure(const bdd& set) const {
  return closure(set, false, false, bddtrue);
}
bdd System::back_zero_time_closure(const bdd& set, const bdd& within) const {
  return closure(set, false, true, within);
}
bdd System::reach(const bdd& set) const {
  return closure(set, true, false, bddtrue);
}
bdd System::back_reach(const bdd& set) const {
  return closure(set, true, true, bddtrue);
}

bdd System::nearest_back(const bdd& set, bool with_tick, const bdd& within, const bdd& goal) const {
  return goal == bddfalse ? goal : closure(set, with_tick, true, within, goal);
}

bdd System::tick_image(const bdd& set) const {
  return tick_.image(set & !settled_) | (set & settled_);
}

bdd System::tick_preimage(const bdd& set, const bdd& within) const {
  return ((tick_.preimage(set) & !settled_) | (set & settled_)) & within;
}

bdd System::time_locks(const bdd& within) const {
  return within & !back_zero_time_closure(tick_.enabled() | settled_, bddtrue);
}

bdd System::stuck(const bdd& within) const {
  bdd moves = tick_.enabled() | settled_;
  for (const StepRelation& step : zero_time_)
    moves |= step.enabled();
  return within & !moves;
}

bool System::zero_time_acyclic() const {
  if (!zero_time_acyclic_)
    zero_time_acyclic_ = no_cycle_proved(*space_, zero_time_);
  return *zero_time_acyclic_;
}

bdd System::zero_time_forever(const bdd& within) const {
  if (zero_time_acyclic())
    return bddfalse;
  // The greatest set of states of `within` that each have a zero-time step into it.
  bdd keep = within & !settled_, before;
  std::uint32_t round = 0;
  do {
    next_group("zero-time cycles", ++round, "");
    before = keep;
    bdd onward = bddfalse;
    for (const StepRelation& step : zero_time_) {
      next_group("zero-time cycles", round, step.name());
      onward |= step.preimage(keep);
    }
    keep &= onward;
  } while (keep != before);
  return keep;
}

} // namespace checker::symbolic
