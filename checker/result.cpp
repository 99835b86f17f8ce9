#include "checker/result.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "checker/checks.hpp"
#include "checker/fingerprint.hpp"

namespace checker {

const char* to_string(Verdict verdict) {
  switch (verdict) {
  case Verdict::holds:
    return "holds";
  case Verdict::violated:
    return "violated";
  default:
    return "incomplete";
  }
}

const char* to_string(Starts starts) {
  switch (starts) {
  case Starts::all:
    return "all";
  case Starts::sampled:
    return "sampled";
  default:
    return "one";
  }
}

std::string describe(const Coverage& c) {
  return std::string(to_string(c.starts)) + ", " + std::to_string(c.count) +
         (c.of ? " of " + std::to_string(*c.of) : std::string()) +
         (c.over.empty() ? std::string() : ": " + c.over) +
         (c.chosen.empty() ? std::string() : " (" + c.chosen + ")");
}

void claim_only_covered(PropertyResult& result) {
  const Coverage& c = result.coverage;
  if (result.verdict != Verdict::holds || c.starts == Starts::all)
    return;
  result.verdict = Verdict::incomplete;
  const std::string over = c.over.empty() ? "the start states" : c.over;
  const std::string chosen = c.chosen.empty() ? "" : " (" + c.chosen + ")";
  if (c.starts == Starts::one)
    result.message =
        "holds from one start state" + chosen + ", not from all of " + over + ": " + result.message;
  else
    result.message = "holds on " + std::to_string(c.count) +
                     (c.of ? " of " + std::to_string(*c.of) : std::string()) + chosen +
                     ", not on all of " + over + ": " + result.message;
}

PropertyResult result_of(const std::string& kind, const Exploration& ex,
                         const tioa::SuccessorGenerator& generator) {
  PropertyResult r;
  r.kind = kind;
  r.states = ex.store.size();
  r.edges = ex.edges;
  r.depth = ex.depth;
  r.seconds = ex.seconds;
  r.threads = ex.threads;
  r.por = ex.reduction;
  r.reduced_states = ex.reduced_states;
  r.store = to_string(ex.store_kind);
  if (ex.fingerprints())
    r.omission_probability = omission_probability(ex.store.size());
  if (ex.tree) {
    std::ostringstream text;
    text << "compressed store: " << ex.store.size() << " states held as keys into "
         << ex.tree->parts() << " shared parts (" << std::fixed << std::setprecision(1)
         << static_cast<double>(ex.store.memory_bytes() + ex.tree->memory_bytes()) / (1 << 20)
         << " MiB)";
    r.notes.push_back(text.str());
  }
  r.time_unit = generator.timed() ? "quanta" : "steps";
  // An exploration covers every state reachable from its start set; a check that explores
  // from a part of what its statement quantifies over says so itself.
  r.coverage = {Starts::all, ex.start_states, ex.start_states, "the start states", ""};
  note_open_inputs(generator.automaton(), r);
  return r;
}

void note_open_inputs(const tioa::Automaton& automaton, PropertyResult& r) {
  for (std::size_t a = 0; a < automaton.actions().size(); ++a) {
    const tioa::ActionSignature& sig = automaton.actions()[a];
    if (sig.kind != tioa::ActionKind::input || !automaton.transitions()[a].bindings.empty())
      continue;
    double points = 1;
    for (const tioa::ParamRange& range : sig.params)
      points *= static_cast<double>(range.hi - range.lo + 1);
    if (points < open_input_points)
      continue;
    std::ostringstream text;
    text << "input '" << sig.name << "' is open (no component outputs all of it), so every "
         << "state tries each of the ";
    if (points < 1e15)
      text << static_cast<std::uint64_t>(points);
    else
      text << std::setprecision(3) << points;
    text << " points of its parameter box: an environment component that outputs it, or "
            "smaller ranges, make the search faster";
    r.notes.push_back(text.str());
  }
}

std::string reachable_states(std::uint64_t count, const Exploration& ex) {
  return reachable_states(count, ex.reduced_states);
}

std::string invariant_broken(std::size_t trace_length, std::uint64_t reduced_states) {
  return std::string("a reachable state breaks the invariant; ") +
         (reduced_states > 0 ? "trace (of the reduced graph): " : "shortest trace: ") +
         std::to_string(trace_length) + " steps";
}

std::string reachable_states(std::uint64_t count, std::uint64_t reduced_states) {
  if (reduced_states > 0)
    return "the " + std::to_string(count) + " reachable states of the reduced graph";
  return std::to_string(count) + " reachable states";
}

void mark_incomplete(PropertyResult& result, const Exploration& ex, const std::string& covered) {
  result.verdict = Verdict::incomplete;
  if (ex.stop == StopReason::state_limit && ex.store.size() == 0) {
    // Only a spent budget stops a run before its first state (Limits::states_left).
    result.message = "state limit reached before this exploration began: the property's "
                     "earlier explorations spent --max-states; " +
                     covered;
    return;
  }
  result.message = std::string(describe(ex.stop)) + " after " + std::to_string(ex.store.size()) +
                   " states to depth " + std::to_string(ex.depth) + ": " + covered;
}

} // namespace checker

namespace checker {

void require_stored_states(const ExploreOptions& options, const std::string& check) {
  if (options.store == StoreKind::fingerprint)
    throw std::invalid_argument(check + " reads the states or edges after the search, which the "
                                        "fingerprint store does not keep: use the exact or the "
                                        "compressed store");
}

void mark_holds(PropertyResult& result, const Exploration& ex, const std::string& message) {
  if (!ex.fingerprints()) {
    result.verdict = Verdict::holds;
    result.message = message;
    return;
  }
  result.verdict = Verdict::incomplete;
  result.message = "holds up to hash collisions, omission probability ≤ " +
                   format_probability(omission_probability(ex.store.size())) + ": " + message;
}

std::string format_probability(double p) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", p);
  return text;
}

} // namespace checker
