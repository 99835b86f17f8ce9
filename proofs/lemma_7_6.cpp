#include "proofs/lemma_7_6.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "checker/simulation_relation.hpp"
#include "checker/trace.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/rmc_matching.hpp"
#include "support/text.hpp"
#include "tioa/successors.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::StateId;
using checker::Verdict;

// The actions of the trace's steps, from `first` on.
std::vector<std::string> actions_from(const checker::Trace& trace, std::size_t first) {
  std::vector<std::string> out;
  for (std::size_t i = first; i < trace.steps.size(); ++i)
    out.push_back(trace.steps[i].action);
  return out;
}

std::string actions_of(const checker::Trace& trace) {
  const std::vector<std::string> out = actions_from(trace, 1);
  return out.empty() ? "(none: a start state)" : support::join(out);
}

} // namespace

PropertyResult check_lemma_7_6(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options, RmcReading reading) {
  const auto started = std::chrono::steady_clock::now();
  const tioa::Automaton full = vlayer(c, reach_faults);
  require_same_layer(layer, full);
  const tioa::SuccessorGenerator gx(layer), gy(full);
  const Matching m = match_family(c, layer, full, window, options, reading);
  const RmcRelation relation(c, full, reading);

  PropertyResult r = checker::result_of("simulation", m.reach, gy);
  note_rmc_reading(c, window, reading, r);
  r.notes.push_back("x steps: " + layer.name() +
                    " with the instance's faults; y steps: VLayer[MC] with failures and "
                    "restarts (the Reach of lemma-7.7); every step matched by one with the same "
                    "label, internal ones too; a tick by a tick");
  if (!m.reach.complete()) {
    mark_incomplete(r, m.reach, "Reach not enumerated, no pair checked");
    return r;
  }

  // The initial pairs: each family state with each related reachable state (`origin`: its id
  // in Reach, for y's trace).
  // The related states are copied out of Reach's store (which may hold them compressed).
  std::vector<StateId> origin;
  std::vector<std::size_t> family_of;
  std::vector<tioa::Word> related_states;
  checker::StateReader read(m.reach);
  for (std::size_t i = 0; i < m.family.size(); ++i)
    for (const StateId y : m.related[i]) {
      const tioa::Word* state = read(y);
      related_states.insert(related_states.end(), state, state + gy.words());
      family_of.push_back(i);
      origin.push_back(y);
    }
  std::vector<checker::StartPair> starts;
  for (std::size_t k = 0; k < origin.size(); ++k)
    starts.push_back({m.family[family_of[k]].data(), related_states.data() + k * gy.words()});
  const checker::SimulationSearch search = checker::search_simulation(
      gx, gy, [&](const tioa::Word* x, const tioa::Word* y) { return relation.related(x, y); },
      starts,
      {.limits = options.limits, .started = started, .memory_held = m.reach.memory_bytes()});

  r.states = search.pairs;
  r.edges = search.edges;
  r.depth = search.depth;
  r.seconds = search.seconds;
  r.figures.emplace_back("covered", "the pairs reachable from the " +
                                        std::to_string(search.initial_pairs) +
                                        " initial pairs (x a family state, y each related "
                                        "reachable state; " +
                                        family_figure(c, m) + ")");
  // A simulation relation is a claim about every related pair; the search covers those
  // reachable from Lemma 7.7's pairs (D24).
  r.coverage = {checker::Starts::sampled, search.pairs, std::nullopt,
                "the pairs related by R_MC (seed 000 §7.3)",
                "the pairs reachable from lemma-7.7's initial pairs, D24"};
  r.figures.emplace_back("pairs", std::to_string(search.pairs));
  r.figures.emplace_back("initial pairs", std::to_string(search.initial_pairs));
  r.figures.emplace_back("Reach", std::to_string(m.reach.store.size()));

  if (search.violation) {
    // The x-trace from its family state, then the step y cannot match; y's trace as a note.
    const checker::SimulationViolation& v = *search.violation;
    std::vector<std::string> why; // what each y step with the same label breaks
    for (const auto& candidate : v.candidates)
      why.push_back(gy.describe(candidate.label) + " breaks " +
                    support::join(relation.broken(v.to.data(), candidate.to.data())));
    const std::vector<std::string> ysteps = actions_from(v.y_trace, 1);
    const checker::Trace to_y = checker::trace_to(gy, m.reach, origin[v.start]);
    r.verdict = Verdict::violated;
    r.trace = v.x_trace;
    r.trace_role = "counterexample";
    r.trace_kind = "simulation-step";
    r.message = "the step " + gx.describe(v.step) + " from x after " +
                std::to_string(v.y_trace.length()) +
                " matched steps has no step of y with the same label to a related state (" +
                (why.empty() ? std::string("y has no such step") : support::join(why, "; ")) + ")";
    r.notes.push_back("y: reached by " + actions_of(to_y) + "; then " +
                      (ysteps.empty() ? std::string("(no step)") : support::join(ysteps)));
    return r;
  }
  if (!search.holds()) {
    r.verdict = Verdict::incomplete;
    r.message = std::string(checker::describe(search.stop)) + " after " +
                std::to_string(search.pairs) +
                " pairs: every step from the pairs expanded was matched";
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "every step and tick of x in each of the " + std::to_string(search.pairs) +
              " pairs reachable from the initial pairs is matched by y with the same label to a "
              "related pair";
  const auto none = std::count_if(m.related.begin(), m.related.end(),
                                  [](const auto& related) { return related.empty(); });
  if (none > 0)
    r.notes.push_back(std::to_string(static_cast<std::uint64_t>(none)) +
                      " family states have no related reachable state (lemma-7.7): no pair "
                      "starts from them");
  return r;
}

PropertyResult check_lemma_7_6(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options) {
  return check_lemma_7_6(c, layer, window, options, RmcReading::loose);
}

} // namespace vlayer_mc
