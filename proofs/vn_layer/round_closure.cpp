#include "proofs/vn_layer/round_closure.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/trace.hpp"
#include "models/vn_layer/round_tags.hpp"
#include "proofs/vn_layer/layer_checks.hpp"
#include "proofs/vn_layer/round_legal_set.hpp"
#include "proofs/vn_layer/round_starts.hpp"
#include "tioa/operators.hpp"

namespace vn_layer {

using checker::StateId;
using checker::Verdict;

namespace {

const char* const legal_set_name = "L_round";

// Marks each state of the result's trace in or out of L_round.
void mark_trace(checker::PropertyResult& r, const RoundLegalSet& legal) {
  r.legal_set_name = legal_set_name;
  r.trace_in_legal_set.clear();
  for (const checker::TraceStep& step : r.trace->steps)
    r.trace_in_legal_set.push_back(legal.contains(step.state.data()));
}

// The trace that leads to `v` from the last state of L_round on v's path of parents (a
// representative, or a state the search canonicalised: only states of L_round are). Every
// step after that state is a step of the automaton from it, and it is in L_round.
checker::Trace round_trace(const tioa::SuccessorGenerator& gen, const checker::Exploration& ex,
                           const RoundView& view, const RoundLegalSet& legal, StateId v) {
  checker::StateReader read(ex);
  const auto in_l_round = [&](StateId w) {
    const tioa::Word* state = read(w);
    return view.round_begins(state) && legal.contains(state);
  };
  std::vector<StateId> path;
  StateId from = v;
  for (; !in_l_round(from); from = ex.parent[from]) { // every start state is in L_round
    if (ex.parent[from] == checker::no_parent)
      throw std::logic_error("vn-layer round-closure: a start state outside L_round");
    path.push_back(from);
  }
  const tioa::Word* first = read(from);
  checker::Trace trace;
  trace.steps.push_back({"", 0, std::vector<tioa::Word>(first, first + ex.state_words)});
  for (auto w = path.rbegin(); w != path.rend(); ++w)
    if (!checker::extend(gen, trace, read(*w)))
      throw std::logic_error("vn-layer round-closure: a parent is no step of the model");
  return trace;
}

std::string count_text(std::uint64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// (a): the round-1 starts the instance reaches. Sets a violation in `r` and returns false
// when one is outside L_round (or an execution stops before time δ); counts them in `firsts`.
bool first_round(const VnConfig& c, const tioa::Automaton& system,
                 const checker::ExploreOptions& options, const RoundLegalSet& legal,
                 checker::PropertyResult& r, std::uint64_t& firsts) {
  const tioa::SuccessorGenerator gen(system);
  const auto epoch = tioa::find_variable<int>(system, "VLBcast.epoch");
  checker::ExploreHooks hooks; // round 0 only: a state of round 1 is entered by a tick
  hooks.expand = [&](const tioa::Word* s) { return tioa::State(s, 0)[epoch] == 0; };
  const checker::Exploration ex = checker::explore(gen, system.start(), options, hooks);
  r = checker::result_of("legal-set", ex, gen);
  r.name = "round-closure";
  note_round_rules(c, r);
  r.figures.emplace_back("(a) states of round 0", std::to_string(ex.store.size()));
  if (!ex.complete()) {
    checker::mark_incomplete(r, ex, "(a) no round-1 start outside L_round found so far");
    return false;
  }
  checker::StateReader read(ex);
  for (StateId v = 0; v < ex.store.size(); ++v) {
    const tioa::Word* state = read(v);
    if (tioa::State(state, 0)[epoch] == 0)
      continue;
    ++firsts;
    if (const auto why = legal.broken(state)) {
      r.verdict = Verdict::violated;
      r.trace = checker::trace_to(gen, ex, v);
      r.trace_role = "counterexample";
      r.trace_kind = "invariant";
      r.message = "(a) the round start at time " + std::to_string(c.delta) +
                  " is outside L_round (" + *why +
                  "); trace: " + std::to_string(r.trace->length()) + " steps";
      mark_trace(r, legal);
      return false;
    }
  }
  if (!ex.stuck.empty()) {
    r.verdict = Verdict::violated;
    r.trace = checker::trace_to(gen, ex, ex.stuck.front());
    r.trace_role = "counterexample";
    r.trace_kind = "time-lock";
    r.message = "(a) an execution stops before time " + std::to_string(c.delta) +
                " (a time-lock); trace: " + std::to_string(r.trace->length()) + " steps";
    mark_trace(r, legal);
    return false;
  }
  return true;
}

} // namespace

tioa::Automaton l_round_layer(const tioa::Automaton& layer, const VnConfig& c) {
  const auto legal = std::make_shared<const RoundLegalSet>(layer, c);
  return tioa::Start(
      layer, [legal](const tioa::State& s) { return legal->contains(s.words()); },
      "L_round (round_legal_set.hpp)");
}

checker::PropertyResult check_round_closure(const VnConfig& c, const tioa::Automaton& layer,
                                            const tioa::Automaton& system,
                                            const checker::ExploreOptions& options,
                                            bool cn_faults) {
  checker::PropertyResult r;
  r.name = "round-closure";
  r.kind = "legal-set";
  if (cn_faults) {
    r.verdict = Verdict::incomplete;
    r.message = "not checked: L_round's closure is about executions without CN failures or "
                "recoveries (Theorem 1's premise, 002:234), and cn_faults=1 allows them";
    return r;
  }
  checker::require_stored_states(options, "round-closure");
  const RoundLegalSet legal(layer, c);

  // (a)
  checker::PropertyResult first;
  std::uint64_t firsts = 0;
  if (!first_round(c, system, options, legal, first, firsts))
    return first;

  // (b) and (c): a round from every class of L_round, and on from the round starts they
  // reach (canonicalised when they are in L_round).
  const auto start = std::make_shared<const tioa::Automaton>(l_round_layer(layer, c));
  const tioa::SuccessorGenerator gen(*start);
  const RoundView view(*start, c);
  checker::ExploreHooks hooks;
  hooks.record_edges = true;
  hooks.canonical = [&](tioa::Word* s) {
    if (view.round_begins(s) && legal.contains(s))
      legal.canonicalise(s);
  };
  // A representative and its round say round 1; a round start outside L_round says a
  // later one (it is not canonicalised) and ends the search there.
  const auto epoch = tioa::find_variable<int>(*start, "VLBcast.epoch");
  hooks.expand = [&](const tioa::Word* s) { return tioa::State(s, 0)[epoch] == last_round; };
  const tioa::StartSet classes =
      tioa::StartSet::listed(layer.layout().bits(), layer.words(), legal.representatives(),
                             "L_round, one state per class (proofs/vn_layer/round_legal_set.hpp)");
  const checker::Exploration ex = checker::explore(gen, classes, options, hooks);
  r = checker::result_of("legal-set", ex, gen);
  r.name = "round-closure";
  r.trace_system = start;
  r.trace_system_name = l_round_system_name;
  r.figures = first.figures;
  r.figures.emplace_back("(a) round starts at time delta", std::to_string(firsts));
  r.figures.emplace_back("(b) L_round classes", std::to_string(ex.start_states));
  r.notes.push_back(
      "L_round (ours, docs/design/vn-layer.md §5.3 check 4): at realtime k*delta, k >= 1, before "
      "any round-k cn-update: (R1) every active CN has its round counters at k and stands on "
      "its target x* != null; (R2) every zone holding an active CN has an alive VN; (R3) every "
      "VN has an empty send-buffer, has handled no trigger of round k and holds no round-k "
      "tag in M or V (their older contents are free); (R4) VLBcast holds nothing; (R5) every "
      "copy of realtime, of a CN's zone and of who is failed agrees");
  r.notes.push_back(
      "(b) and (c) start from one state per class of L_round: states that differ only in M's "
      "and V's older contents, older round tags, the observers and a failed CN's internal "
      "variables have the same rounds, unless a VN computes targets in a round in which it "
      "handled no exchange-trigger (it would count M's older entries); the check looks for "
      "that case in every round it explores (proofs/vn_layer/round_legal_set.hpp)");
  note_round_rules(c, r);
  if (!ex.complete()) {
    checker::mark_incomplete(r, ex, "no round from L_round that leaves it found so far");
    return r;
  }
  RoundWalker walker(ex, view);
  const auto set_trace = [&](StateId v, const char* kind) {
    r.trace = round_trace(gen, ex, view, legal, v);
    r.trace_role = "counterexample";
    r.trace_kind = kind;
    mark_trace(r, legal);
  };
  checker::StateReader read(ex);
  for (StateId v = 0; v < ex.store.size(); ++v) // the model's bound first: past it, no verdict
    if (legal.overflowed(read(v))) {
      set_trace(v, "overflow");
      r.verdict = Verdict::incomplete;
      r.message = "a send found the model's places taken (overflow), so the rounds explored "
                  "are not the layer's; trace to the first such state";
      return r;
    }
  std::uint64_t later_starts = 0;
  for (StateId v = 0; v < ex.store.size(); ++v) {
    if (!walker.is_later_start(v))
      continue;
    ++later_starts;
    if (const auto why = legal.broken(read(v))) {
      set_trace(v, "invariant");
      r.verdict = Verdict::violated;
      r.message = "(b) a round from an L_round state ends outside L_round (" + *why +
                  "); trace: the round, " + std::to_string(r.trace->length()) + " steps";
      return r;
    }
  }
  r.figures.emplace_back("(b) round starts reached", std::to_string(later_starts));
  if (!ex.stuck.empty()) {
    set_trace(ex.stuck.front(), "time-lock");
    r.verdict = Verdict::violated;
    r.message = "(c) a round from an L_round state has a time-lock (" +
                count_text(ex.stuck.size(), "state", "states") +
                " with no step); trace: the round, " + std::to_string(r.trace->length()) + " steps";
    return r;
  }
  for (StateId v = 0; v < ex.store.size(); ++v) {
    if (const auto h = legal.stale_reader(read(v))) {
      set_trace(v, "stale-read");
      r.trace_role = "witness";
      r.verdict = Verdict::incomplete;
      r.message = "VN_" + std::to_string(*h) +
                  " computes targets in a round in which it handled no exchange-trigger, so it "
                  "may count M's entries of earlier rounds, which the classes of L_round ignore: "
                  "the representatives do not cover their classes; trace: the round";
      return r;
    }
  }
  r.coverage.starts = checker::Starts::all;
  r.coverage.count = ex.start_states;
  r.coverage.of = ex.start_states;
  r.coverage.over = "the classes of L_round (and, for (a), the instance's start states)";
  checker::mark_holds(r, ex,
                      "(a) the " + count_text(firsts, "round start", "round starts") + " at time " +
                          std::to_string(c.delta) + " are in L_round; (b) every round from the " +
                          count_text(ex.start_states, "class", "classes") +
                          " of L_round ends in L_round; (c) no time-lock in " +
                          std::to_string(ex.store.size()) + " states of those rounds");
  return r;
}

} // namespace vn_layer
