#include "proofs/vn_layer/round_timing_figures.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/run_limits.hpp"
#include "models/vn_layer/names.hpp"
#include "tioa/operators.hpp"

namespace vn_layer {

namespace {

enum class Timed { none, cn_update, vn_update, target_update };

struct Figure {
  std::string name, formula;
  int stated = 0;
  int worst = -1; // none seen
  void note(int value) { worst = std::max(worst, value); }
};

} // namespace

void add_round_timing_figures(const VnConfig& c, const tioa::Automaton& system,
                              const checker::ExploreOptions& options, checker::PropertyResult& r) {
  const tioa::SuccessorGenerator gen(system);
  const checker::Exploration ex = checker::explore(gen, system.start(), options);
  if (!ex.complete()) {
    r.notes.push_back("the measured figures were not computed: their exploration stopped on "
                      "a limit");
    return;
  }
  // Which deliveries are timed, by action.
  const auto& actions = system.actions();
  std::vector<Timed> timed(actions.size(), Timed::none);
  const Lattice lattice = c.lattice();
  for (std::size_t a = 0; a < actions.size(); ++a) {
    for (RegionId h = 0; h < lattice.regions(); ++h) {
      if (actions[a].name == names::receive_cn_update(h))
        timed[a] = Timed::cn_update;
      if (actions[a].name == names::receive_vn_update(h))
        timed[a] = Timed::vn_update;
    }
    for (int i = 0; i < c.cns; ++i)
      if (actions[a].name == names::receive_target_update(i))
        timed[a] = Timed::target_update;
  }
  // realtime mod δ: VLBcast's copy (C21), which no failure stops.
  const auto phase = tioa::find_variable<int>(system, "VLBcast.phase");
  std::vector<tioa::Variable<int>> x, target;
  for (int i = 0; i < c.cns; ++i) {
    x.push_back(tioa::find_variable<int>(system, names::cn_name(i) + ".x"));
    target.push_back(tioa::find_variable<int>(system, names::cn_name(i) + ".target"));
  }
  Figure cn_update{"cn-update delivered", "d_v", c.d_v};
  Figure vn_update{"vn-update delivered", "d_MMT + 3d_v + eps", c.d_mmt + 3 * c.d_v + c.eps};
  Figure target_update{"target-update after its trigger", "d_MMT + 2d_v", c.d_mmt + 2 * c.d_v};
  Figure arrival{"CN on target", "delta", c.delta};

  std::vector<tioa::Word> scratch(gen.words() + 1, 0);
  checker::PropertyLimitPoll poll(options.limits);
  checker::StateReader read(ex);
  for (checker::StateId v = 0; v < ex.store.size(); ++v) {
    if (poll.reached(v)) {
      r.notes.push_back("the measured figures were not computed: a limit was met while "
                        "they were measured");
      return;
    }
    const tioa::Word* from = read(v);
    const tioa::State before(from, 0);
    const int now = before[phase];
    gen.successors(from, scratch.data(), [&](const tioa::Word* to, const tioa::StepLabel& step) {
      if (step.is_tick()) {
        const tioa::State after(to, 0);
        const int at = after[phase] == 0 ? c.delta : after[phase];
        // A CN that was not on its target before the tick and is after it.
        const auto on_target = [&](const tioa::State& s, std::size_t i) {
          return !s.is_bottom(target[i]) && s[x[i]] == s[target[i]];
        };
        for (std::size_t i = 0; i < x.size(); ++i)
          if (on_target(after, i) && !on_target(before, i))
            arrival.note(at);
        return;
      }
      const tioa::Params& m = step.params;
      switch (timed[step.action]) {
      case Timed::cn_update: // (i, loc, round)
        cn_update.note(now + m[2] * c.delta);
        break;
      case Timed::vn_update: // (g, n, round)
        vn_update.note(now + m[2] * c.delta);
        break;
      case Timed::target_update: { // at the CN, from its trigger in this round or the last
        const int since = now - c.target_phase();
        target_update.note(since >= 0 ? since : since + c.delta);
        break;
      }
      case Timed::none:
        break;
      }
    });
  }
  std::string summary;
  for (const Figure* f : {&cn_update, &vn_update, &target_update, &arrival}) {
    const std::string measured = f->worst < 0 ? "none" : std::to_string(f->worst);
    r.figures.emplace_back(f->name + " measured", measured);
    r.figures.emplace_back(f->name + " stated",
                           std::to_string(f->stated) + " (" + f->formula + ")");
    summary += (summary.empty() ? "" : ", ") + f->name + " " + measured +
               (f->worst > f->stated ? " > " : " <= ") + std::to_string(f->stated);
  }
  r.notes.push_back("worst times over every step of the " + std::to_string(ex.store.size()) +
                    " reachable states, in quanta from the round's start (a delivery) or the "
                    "CN's target-trigger (a target-update): " +
                    summary);
}

} // namespace vn_layer
