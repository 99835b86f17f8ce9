#include "proofs/lemma_7_3.hpp"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "checker/checks.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "proofs/vlayer_mc/stabilisation_common.hpp"
#include "proofs/vlayer_mc/symbolic_starts.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;

// The clauses of `clauses` that the last state of the trace outside `legal` breaks.
std::string last_outside(const PropertyResult& r, const tioa::StatePredicate& legal,
                         const ClauseCheck& clauses) {
  if (!r.trace)
    return "";
  for (auto it = r.trace->steps.rbegin(); it != r.trace->steps.rend(); ++it) {
    const tioa::State s(it->state.data(), 0);
    if (!legal(s)) {
      std::string broken;
      for (const auto& clause : clauses(s))
        broken += (broken.empty() ? "" : ", ") + clause;
      return "the last state outside, at time " + std::to_string(it->time) + " after " +
             (it->action.empty() ? std::string("the start") : it->action) + ", breaks " + broken;
    }
  }
  return "";
}

// The notes and trace system every Lemma 7.3 result carries.
PropertyResult finish(PropertyResult r, const VlConfig& c, const ArbitraryStarts& starts,
                      const tioa::Automaton& layer) {
  r.notes.push_back("the bound: time t > eps_sample = " + std::to_string(c.eps_sample) +
                    " is, in whole quanta, t = eps_sample + 1");
  r.notes.push_back(faults_note(starts.faults, c.dr_rule));
  r.notes.push_back(junk_note(starts.junk));
  // Its trace is one of the layer with junk slots (D31).
  r.trace_system = std::make_shared<const tioa::Automaton>(layer);
  r.trace_system_name = u_layer_name;
  note_repairs(c, r);
  note_round_length(c, r);
  return r;
}

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// Every start state at once (symbolic_starts.hpp). A worst case above the bound, and a
// start state that reaches a time-lock or endless zero-time steps, are explored again
// explicitly from that one start state: the counterexample is then check_stabilisation's,
// a real trace that replays, and its worst time must be the symbolic one.
PropertyResult check_symbolically(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                                  const checker::ExploreOptions& options) {
  const tioa::Automaton layer = u_layer(c, starts);
  const tioa::StatePredicate legal = l1mc(c, layer, window);
  const std::uint64_t bound = static_cast<std::uint64_t>(c.eps_sample) + 1;
  const SymbolicRun run =
      stabilise_from_u(c, starts, layer, l1mc_conjuncts(c, layer, window), bound, options.limits);
  const checker::symbolic::StabilisationResult& s = run.result;
  const std::string what = "Lemma 7.3 (in L1MC from any t > eps_sample on)";
  const bool fits = s.start_states < 1.8e19; // (in 64 bits)
  const checker::Coverage coverage{
      checker::Starts::all, fits && !s.stopped ? static_cast<std::uint64_t>(s.start_states) : 0,
      fits ? std::optional<std::uint64_t>(s.start_states) : std::nullopt, u_layer_name,
      s.stopped ? "decided symbolically, stopped at the time limit"
                : "every one, decided symbolically (binary decision diagrams)"};
  const std::string figure =
      scientific(s.start_states) + " start states (R(env): " + scientific(run.environment_states) +
      " states), " + scientific(s.reachable) + " reachable, " + std::to_string(s.layers) +
      " time layers, " + std::to_string(run.learned_cubes) + " cubes learned, " +
      scientific(s.time_locked) + " time-locked, " + scientific(s.zero_time_forever) +
      " with endless zero-time steps, " + scientific(run.seconds) + " s";
  PropertyResult r;
  if (s.stopped) {
    r.kind = "stabilisation";
    r.verdict = checker::Verdict::incomplete;
    r.message = what + ": the symbolic computation stopped at the time limit";
  } else {
    const bool late = !s.worst || *s.worst > bound;
    const bool stops_time = s.time_locked > 0 || s.zero_time_forever > 0;
    const std::vector<tioa::Word>& witness = late ? s.worst_start : s.time_lock_start;
    if ((late || stops_time) && witness.empty())
      throw std::logic_error("lemma-7.3: the symbolic computation found no start state for "
                             "what it found");
    if (!witness.empty()) {
      const StateList one{layer.words(), witness};
      PropertyResult m = checker::check_stabilisation(
          tioa::Start(layer, one.start(layer, u_layer_name)), legal, options);
      if (late && s.worst && m.worst_time != s.worst)
        throw std::logic_error("lemma-7.3: the symbolic worst time " + std::to_string(*s.worst) +
                               " is not the explicit one from its start state");
      const std::string detail = last_outside(m, legal, l1mc_clauses(c, layer, window));
      r = judge(std::move(m), bound, what, true, true, detail);
      if (!late && r.verdict == checker::Verdict::holds) {
        // The explicit run from that start state meets the bound: the time-lock or the
        // endless zero-time steps are not judged by the layers, so no claim of holds.
        r.verdict = checker::Verdict::incomplete;
        r.message = what + ": worst time " + std::to_string(*s.worst) + " within the bound, but " +
                    scientific(s.time_locked) + " reachable states are time-locked and " +
                    scientific(s.zero_time_forever) + " can take zero-time steps for ever";
      }
      r.seconds += run.seconds; // (the symbolic part, then the explicit run)
      r.notes.push_back("the trace: explored explicitly from the start state the symbolic "
                        "computation picked (one of those with the latest time outside L1MC)");
    } else {
      PropertyResult m;
      m.kind = "stabilisation";
      m.verdict = checker::Verdict::holds;
      m.time_unit = "quanta";
      m.worst_time = s.worst;
      m.states = s.reachable < 1.8e19 ? static_cast<std::uint64_t>(s.reachable) : 0;
      m.seconds = run.seconds;
      r = judge(std::move(m), bound, what, true, true, "");
      r.message += ", from every start state";
    }
  }
  r.figures.emplace_back("covered", s.stopped
                                        ? "none decided: the symbolic computation of " +
                                              scientific(s.start_states) +
                                              " start states stopped at the time limit"
                                        : "every start state of " + std::string(u_layer_name) +
                                              ": " + scientific(s.start_states) + " (symbolic)");
  r.figures.emplace_back("symbolic", figure);
  r.coverage = coverage;
  return finish(std::move(r), c, starts, layer);
}

} // namespace

PropertyResult check_lemma_7_3(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  if (starts.symbolic)
    return check_symbolically(c, window, starts, options);
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate legal = l1mc(c, u.layer, window);
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)")), legal,
      options);
  const std::string detail = last_outside(m, legal, l1mc_clauses(c, u.layer, window));
  PropertyResult r =
      judge(std::move(m), static_cast<std::uint64_t>(c.eps_sample) + 1,
            "Lemma 7.3 (in L1MC from any t > eps_sample on)", u.exhaustive, true, detail);
  r.figures.emplace_back("covered", u.covered);
  r.coverage = u.coverage;
  return finish(std::move(r), c, starts, u.layer);
}

} // namespace vlayer_mc
