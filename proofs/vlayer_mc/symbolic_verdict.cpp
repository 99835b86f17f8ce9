#include "proofs/vlayer_mc/symbolic_verdict.hpp"

#include <cstdio>
#include <optional>
#include <stdexcept>

#include "checker/checks.hpp"
#include "models/vlayer_mc/state_list.hpp"
#include "proofs/vlayer_mc/stabilisation_common.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

using checker::PropertyResult;

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

namespace {

// check_stabilisation from the one state `start` of `layer`.
PropertyResult explicit_from(const tioa::Automaton& layer, const std::vector<tioa::Word>& start,
                             const SymbolicClaim& claim, const checker::ExploreOptions& options) {
  const StateList one{layer.words(), start};
  const tioa::Automaton from = tioa::Start(layer, one.start(layer, "the start state picked"));
  return claim.settled ? checker::check_stabilisation(from, claim.legal, claim.settled, options)
                       : checker::check_stabilisation(from, claim.legal, options);
}

PropertyResult judged(const SymbolicRun& run, const tioa::Automaton& layer,
                      const SymbolicClaim& claim, const checker::ExploreOptions& options) {
  const checker::symbolic::StabilisationResult& s = run.result;
  PropertyResult r;
  if (s.stopped) {
    r.kind = "stabilisation";
    r.verdict = checker::Verdict::incomplete;
    r.message = claim.what + ": the symbolic computation stopped at " + run.stopped_by;
    r.seconds = run.seconds;
    return r;
  }
  const bool late = !s.worst || *s.worst > claim.bound;
  const bool stops_time = s.time_locked > 0 || s.zero_time_forever > 0;
  const std::vector<tioa::Word>& witness = late ? s.worst_start : s.time_lock_start;
  if ((late || stops_time) && witness.empty())
    throw std::logic_error(claim.what + ": the symbolic computation found no start state for "
                                        "what it found");
  if (witness.empty()) {
    PropertyResult m;
    m.kind = "stabilisation";
    m.verdict = checker::Verdict::holds;
    m.time_unit = "quanta";
    m.worst_time = s.worst;
    m.states = s.reachable < 1.8e19 ? static_cast<std::uint64_t>(s.reachable) : 0;
    m.seconds = run.seconds;
    r = judge(std::move(m), claim.bound, claim.what, claim.exhaustive, claim.exact, "");
    r.message += ", from every start state";
    return r;
  }
  PropertyResult m = explicit_from(layer, witness, claim, options);
  if (late && s.worst && m.worst_time != s.worst)
    throw std::logic_error(claim.what + ": the symbolic worst time " + std::to_string(*s.worst) +
                           " is not the explicit one from its start state");
  const std::string detail = claim.detail ? claim.detail(m) : "";
  r = judge(std::move(m), claim.bound, claim.what, claim.exhaustive, claim.exact, detail);
  if (!late && r.verdict == checker::Verdict::holds) {
    // The explicit run from that start state meets the bound: the time-lock or the endless
    // zero-time steps are not judged by the layers, so no claim of holds.
    r.verdict = checker::Verdict::incomplete;
    r.message = claim.what + ": worst time " + std::to_string(s.worst.value_or(0)) +
                " within the bound, but " + scientific(s.time_locked) +
                " reachable states are time-locked and " + scientific(s.zero_time_forever) +
                " can take zero-time steps for ever";
  }
  r.seconds += run.seconds; // (the symbolic part, then the explicit run)
  r.notes.push_back("the trace: explored explicitly from the start state the symbolic "
                    "computation picked (one of those with the latest time outside the set)");
  return r;
}

} // namespace

PropertyResult judge_symbolic(const SymbolicRun& run, const tioa::Automaton& layer,
                              const SymbolicClaim& claim, const checker::ExploreOptions& options) {
  const checker::symbolic::StabilisationResult& s = run.result;
  PropertyResult r = judged(run, layer, claim, options);
  const bool fits = s.start_states < 1.8e19; // (in 64 bits)
  // (A count past 64 bits is left 0 and given in words.)
  r.coverage = {
      checker::Starts::all, fits && !s.stopped ? static_cast<std::uint64_t>(s.start_states) : 0,
      fits && !s.stopped ? std::optional<std::uint64_t>(s.start_states) : std::nullopt, claim.over,
      s.stopped
          ? "decided symbolically, stopped at " + run.stopped_by
          : std::string("every one") +
                (fits ? "" : " (" + scientific(s.start_states) + ", more than 64 bits count)") +
                ", decided symbolically (binary decision diagrams)"};
  r.figures.emplace_back("covered", s.stopped ? "none decided: the symbolic computation stopped "
                                                "at " +
                                                    run.stopped_by
                                              : "every start state of " + claim.over + ": " +
                                                    scientific(s.start_states) + " (symbolic)");
  r.figures.emplace_back(
      "symbolic",
      scientific(s.start_states) + " start states (R(env): " + scientific(run.environment_states) +
          " states), " + scientific(s.reachable) + " reachable, " + std::to_string(s.layers) +
          " time layers, " + std::to_string(run.learned_cubes) + " cubes learned, " +
          scientific(s.time_locked) + " time-locked, " + scientific(s.zero_time_forever) +
          " with endless zero-time steps, " + scientific(run.seconds) + " s");
  return r;
}

std::optional<PropertyResult> judge_symbolic_part(const SymbolicRun& run, double all_states,
                                                  const std::string& part,
                                                  const tioa::Automaton& layer,
                                                  const SymbolicClaim& claim,
                                                  const checker::ExploreOptions& options) {
  const checker::symbolic::StabilisationResult& s = run.result;
  if (s.stopped || (s.worst && *s.worst <= claim.bound))
    return std::nullopt;
  PropertyResult r = judge_symbolic(run, layer, claim, options);
  const auto count = [](double x) {
    return x < 1.8e19 ? std::optional<std::uint64_t>(static_cast<std::uint64_t>(x)) : std::nullopt;
  };
  const std::string of = scientific(s.start_states) + " of " + scientific(all_states);
  r.coverage.starts = checker::Starts::sampled;
  r.coverage.count = count(s.start_states).value_or(0);
  r.coverage.of = count(all_states);
  r.coverage.chosen = part + " (" + of +
                      " start states), decided symbolically first: a "
                      "worst time past the bound there is one for every start state";
  for (auto& [name, value] : r.figures)
    if (name == "covered")
      value = part + ": " + of + " start states (symbolic); the others not needed";
  std::erase_if(r.figures, [](const auto& figure) { return figure.first == "measured"; });
  const std::string worst =
      s.worst ? std::to_string(*s.worst) + " " + r.time_unit : std::string("none");
  r.figures.emplace_back("worst time of the part", worst + " (every start state: at least that)");
  r.message += " (" + part + "; over every start state the worst time is at least that)";
  r.worst_time.reset();
  r.last_time_outside.reset();
  return r;
}

PropertyResult part_when_whole_stopped(PropertyResult from_part, const SymbolicRun& whole) {
  from_part.notes.push_back("every start state: the symbolic computation stopped at " +
                            whole.stopped_by + ", so the worst time over all of them is not known");
  from_part.seconds = whole.seconds;
  return from_part;
}

} // namespace vlayer_mc
