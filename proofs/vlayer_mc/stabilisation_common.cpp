#include "proofs/vlayer_mc/stabilisation_common.hpp"

#include "checker/explorer.hpp"
#include "checker/run_limits.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "tioa/successors.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;
using tioa::Word;

} // namespace

StateList reached_where(const tioa::Automaton& system, const tioa::StatePredicate& keep,
                        const checker::ExploreOptions& options, bool& complete) {
  const tioa::SuccessorGenerator generator(system);
  const checker::Exploration ex = checker::explore(generator, system.start(), options);
  complete = complete && ex.complete();
  StateList out{system.words(), {}};
  // The list is built outside the exploration: the property's limits bound it too.
  checker::PropertyLimitPoll limit(options.limits);
  checker::StateReader read(ex);
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    if (limit.reached(id)) {
      complete = false;
      break;
    }
    const Word* w = read(id);
    if (keep(tioa::State(w, 0)))
      out.data.insert(out.data.end(), w, w + system.words());
  }
  return out;
}

const char* const lmc_measure_note =
    "an execution is counted in LMC from the first state that is in ResetMC, or a ResetMC state "
    "but for targets its due cn-updates overwrite (D30), or in the known part of LMC (D29): an "
    "upper bound on the time into LMC, so a time above the bound, or a "
    "cycle that never gets there, is reported as not confirmed, not as a counterexample";

std::string describe_known(const KnownLmc& known) {
  return std::to_string(known.size()) + " classes (D29) of the states reachable from " +
         std::to_string(known.family_size()) +
         " ResetMC states (the reset family with every combination of failed nodes)" +
         (known.complete() ? "" : ", stopped on a limit");
}

PropertyResult judge(PropertyResult m, std::uint64_t bound, const std::string& what,
                     bool exhaustive, bool exact, const std::string& detail) {
  m.figures.emplace_back("bound", std::to_string(bound) + " " + m.time_unit);
  if (m.verdict == Verdict::violated && !exact) {
    // A cycle that never meets the settled states: not a counterexample, since LMC is
    // only known in part.
    m.verdict = Verdict::incomplete;
    m.trace_role = "witness";
    m.message =
        what + " not confirmed: " + m.message + " (outside ResetMC and the known part of LMC)";
    return m;
  }
  if (m.verdict == Verdict::incomplete || m.verdict == Verdict::violated) {
    if (m.verdict == Verdict::violated)
      m.message = what + " fails: " + m.message + (detail.empty() ? "" : "; " + detail);
    return m;
  }
  const std::uint64_t worst = m.worst_time.value_or(0);
  m.figures.emplace_back("measured", std::to_string(worst) + " " + m.time_unit);
  const std::string measured = "measured worst time " + std::to_string(worst) + " " + m.time_unit +
                               " against the bound " + std::to_string(bound);
  if (worst > bound) {
    m.trace_role = exact ? "counterexample" : "witness";
    m.verdict = exact ? Verdict::violated : Verdict::incomplete;
    m.message = what + (exact ? " fails: " : " not confirmed: ") + measured +
                (detail.empty() ? "" : "; " + detail);
    return m;
  }
  m.verdict = exhaustive ? Verdict::holds : Verdict::incomplete;
  m.message = what + (exhaustive ? " holds: " : " holds on every start state sampled: ") + measured;
  return m;
}

tioa::StatePredicate in_measured_lmc(const VlConfig& c, const tioa::Automaton& layer,
                                     MWindow window, const KnownLmc& known) {
  return [reset = reset_mc_or_targetless(c, layer, window), &known](const tioa::State& s) {
    return reset(s) || known.contains(s);
  };
}

PropertyResult with_common_notes(PropertyResult r, const VlConfig& c, const ArbitraryStarts& starts,
                                 const tioa::Automaton& layer) {
  r.notes.push_back(faults_note(starts.faults, c.dr_rule));
  r.notes.push_back(junk_note(starts.junk));
  r.trace_system = std::make_shared<const tioa::Automaton>(layer);
  r.trace_system_name = u_layer_name;
  note_repairs(c, r);
  note_round_length(c, r);
  return r;
}

} // namespace vlayer_mc
