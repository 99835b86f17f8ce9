#include "proofs/vlayer_mc/simulation.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/state_store.hpp"
#include "checker/trace.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/slots.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "proofs/vlayer_mc/rmc_matching.hpp"
#include "tioa/successors.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::StateId;
using checker::Verdict;
using tioa::Slot;
using tioa::Word;

// The value of a non-⊥ integer slot.
std::int64_t value(const Word* s, const Slot& slot) {
  return slot.lo + static_cast<std::int64_t>(tioa::State(s, 0).code(slot));
}

std::string count(std::uint64_t n) {
  return std::to_string(n);
}

std::string joined(const std::vector<std::string>& parts, const char* separator = ", ") {
  std::string out;
  for (const auto& part : parts)
    out += (out.empty() ? "" : separator) + part;
  return out;
}

checker::Trace single_state(const std::vector<Word>& state, std::uint32_t words) {
  checker::Trace trace;
  trace.steps.push_back({"", 0, std::vector<Word>(state.begin(), state.begin() + words)});
  return trace;
}

std::string actions_of(const checker::Trace& trace) {
  std::vector<std::string> out;
  for (std::size_t i = 1; i < trace.steps.size(); ++i)
    out.push_back(trace.steps[i].action);
  return out.empty() ? "(none: a start state)" : joined(out);
}

std::string family_figure(const VlConfig& c, const Matching& m) {
  return "the " + describe_reset_family(c) + "; " + count(m.in_reset_mc) +
         " of them meet Def 7.2 " +
         "with the window read; the family, not all of ResetMC (V_u, VW's ages and GPS ages " +
         "are left free by Def 7.2)";
}

void common_notes(const VlConfig& c, MWindow window, RmcReading reading, PropertyResult& r) {
  r.notes.push_back(std::string("R_MC, ") + to_string(reading) +
                    " reading: parts (1)-(4) of seed 000 §7.3 and, for the parts Appendix C "
                    "would give, every live node's state equal (README, R_MC, D17-D21)" +
                    (reading == RmcReading::strict
                         ? ""
                         : "; CN's target may be ⊥ or x_p on either side while its cn-update is "
                           "due (D20)") +
                    (reading == RmcReading::loose_reg
                         ? "; Vbcast.reg(p) may differ while p's GPSupdate is due and nothing "
                           "reads it first (D21, beyond the printed part (4))"
                         : ""));
  r.notes.push_back(window == MWindow::closed
                        ? "ResetMC read with the window [0, e + 2d + 2ε] of Def 7.1(2) (F1)"
                        : "ResetMC read with Def 7.1(2) as printed");
  note_round_length(c, r);
}

} // namespace

// ---------------------------------------------------------------------------------------
// Lemma 7.7: the matching of the family

PropertyResult check_lemma_7_7(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options, RmcReading reading) {
  const tioa::Automaton full = vlayer(c, reach_faults);
  require_same_layer(layer, full);
  const tioa::SuccessorGenerator generator(full);
  const Matching m = match_family(c, layer, full, window, options, reading);
  PropertyResult r = checker::result_of("simulation", m.reach, generator);
  r.figures.emplace_back("covered", family_figure(c, m));
  r.figures.emplace_back("Reach", count(m.reach.store.size()) + " states of " +
                                      every_placement(c, full).description());
  common_notes(c, window, reading, r);
  if (!m.reach.complete()) {
    mark_incomplete(r, m.reach, "Reach not enumerated, no family state matched");
    return r;
  }

  // Per reading: how many family states are unmatched, and the first of them.
  std::array<std::uint64_t, 3> unmatched{0, 0, 0};
  std::array<std::optional<std::size_t>, 3> first;
  std::uint64_t pairs = 0;
  for (std::size_t i = 0; i < m.family.size(); ++i) {
    pairs += m.related[i].size();
    for (std::size_t k = 0; k < readings.size(); ++k)
      if (!m.matched[i][k]) {
        ++unmatched[k];
        if (!first[k])
          first[k] = i;
      }
  }
  const std::size_t chosen = static_cast<std::size_t>(
      std::find(readings.begin(), readings.end(), reading) - readings.begin());
  const std::uint64_t size = m.family.size();
  for (std::size_t k = 0; k < readings.size(); ++k)
    r.figures.emplace_back(std::string("matched (") + to_string(readings[k]) + ")",
                           count(size - unmatched[k]) + " of " + count(size));
  r.figures.emplace_back("related pairs", count(pairs));
  const Slot loc = need_slot(full, "RW.loc[0]", "R_MC");
  for (std::size_t k = 0; k < readings.size(); ++k)
    if (k != chosen && first[k]) {
      const auto& x = m.family[*first[k]];
      const RmcRelation other(c, full, readings[k]);
      r.notes.push_back(std::string(to_string(readings[k])) + " reading: " + count(unmatched[k]) +
                        " family states have no related reachable state; the first has robot 0 "
                        "at point " +
                        std::to_string(value(x.data(), loc)) +
                        " and the closest reachable state breaks " +
                        joined(closest(other, m.reach, x.data()).second));
    }
  if (first[chosen]) {
    const auto& x = m.family[*first[chosen]];
    const RmcRelation relation(c, full, reading);
    r.verdict = Verdict::violated;
    r.trace = single_state(x, full.words());
    r.trace_role = "counterexample";
    r.trace_kind = "invariant";
    r.message = count(unmatched[chosen]) + " of the " + count(size) +
                " ResetMC states of the family have no related reachable state; the state "
                "shown is the first, and the closest reachable state breaks " +
                joined(closest(relation, m.reach, x.data()).second);
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "each of the " + count(size) +
              " ResetMC states of the family is related by R_MC to a reachable state of "
              "VLayer[MC] (" +
              count(pairs) + " related pairs among " + count(m.reach.store.size()) +
              " reachable states)";
  return r;
}

PropertyResult check_lemma_7_7(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options) {
  return check_lemma_7_7(c, layer, window, options, RmcReading::loose);
}

// ---------------------------------------------------------------------------------------
// Lemma 7.6: the pair graph

PropertyResult check_lemma_7_6(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options, RmcReading reading) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  const tioa::Automaton full = vlayer(c, reach_faults);
  require_same_layer(layer, full);
  const tioa::SuccessorGenerator gx(layer), gy(full);
  const std::uint32_t w = layer.words();
  const Matching m = match_family(c, layer, full, window, options, reading);
  const RmcRelation relation(c, full, reading);

  PropertyResult r = checker::result_of("simulation", m.reach, gy);
  common_notes(c, window, reading, r);
  r.notes.push_back("x steps: " + layer.name() +
                    " with the instance's faults; y steps: VLayer[MC] with failures and "
                    "restarts (the Reach of lemma-7.7); every step matched by one with the same "
                    "label, internal ones too; a tick by a tick");
  if (!m.reach.complete()) {
    mark_incomplete(r, m.reach, "Reach not enumerated, no pair checked");
    return r;
  }

  // Pairs (x, y) as 2w words; ids in breadth-first order.
  checker::StateStore pairs(2 * w);
  std::vector<StateId> parent;
  std::vector<tioa::StepLabel> via; // the x step (= the y step's label) into the pair
  std::vector<StateId> origin;      // for an initial pair: y's id in Reach
  std::vector<std::uint32_t> level;
  std::vector<Word> pair(2 * w + 1, 0);
  const auto add = [&](const Word* x, const Word* y, StateId from, const tioa::StepLabel& label,
                       StateId reach_id) {
    std::copy(x, x + w, pair.begin());
    std::copy(y, y + w, pair.begin() + w);
    const auto [id, fresh] = pairs.insert(pair.data(), checker::hash_state(pair.data(), 2 * w));
    if (fresh) {
      parent.push_back(from);
      via.push_back(label);
      origin.push_back(reach_id);
      level.push_back(from == checker::no_parent ? 0 : level[from] + 1);
    }
  };
  for (std::size_t i = 0; i < m.family.size(); ++i)
    for (const StateId y : m.related[i])
      add(m.family[i].data(), m.reach.store.state(y), checker::no_parent, {}, y);
  const std::uint64_t initial = pairs.size();

  struct Successor {
    tioa::StepLabel label;
    std::vector<Word> state;
  };
  std::vector<Successor> ys;
  std::vector<Word> scratch_x(w + 1, 0), scratch_y(w + 1, 0), here(2 * w + 1, 0);
  std::uint64_t edges = 0;
  checker::StopReason stop = checker::StopReason::finished;
  std::optional<std::pair<StateId, tioa::StepLabel>> unmatched;
  std::vector<Word> unmatched_to;
  std::vector<std::string> unmatched_why; // what each y step with the same label breaks
  for (StateId id = 0; id < pairs.size() && !unmatched; ++id) {
    if (options.limits.max_states != 0 && pairs.size() >= options.limits.max_states) {
      stop = checker::StopReason::state_limit;
      break;
    }
    if (options.limits.max_seconds > 0 &&
        std::chrono::duration<double>(Clock::now() - started).count() >
            options.limits.max_seconds) {
      stop = checker::StopReason::time_limit;
      break;
    }
    if (options.limits.max_memory_bytes != 0 &&
        pairs.memory_bytes() + m.reach.memory_bytes() > options.limits.max_memory_bytes) {
      stop = checker::StopReason::memory_limit;
      break;
    }
    std::copy(pairs.state(id), pairs.state(id) + 2 * w, here.begin());
    const Word* x = here.data();
    std::vector<Word> y(here.begin() + w, here.end());
    ys.clear();
    gy.successors(y.data(), scratch_y.data(), [&](const Word* to, const tioa::StepLabel& label) {
      ys.push_back({label, std::vector<Word>(to, to + w + 1)});
    });
    gx.successors(x, scratch_x.data(), [&](const Word* to, const tioa::StepLabel& label) {
      if (unmatched)
        return;
      bool matched = false;
      for (const Successor& s : ys)
        if (s.label.action == label.action && (label.is_tick() || s.label.params == label.params) &&
            relation.related(to, s.state.data())) {
          matched = true;
          ++edges;
          add(to, s.state.data(), id, label, 0);
        }
      if (!matched) {
        unmatched.emplace(id, label);
        unmatched_to.assign(to, to + w);
        for (const Successor& s : ys)
          if (s.label.action == label.action && (label.is_tick() || s.label.params == label.params))
            unmatched_why.push_back(gy.describe(s.label) + " breaks " +
                                    joined(relation.broken(to, s.state.data())));
      }
    });
  }

  r.states = pairs.size();
  r.edges = edges;
  r.depth = level.empty() ? 0 : *std::max_element(level.begin(), level.end());
  r.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  r.figures.emplace_back("covered", "the pairs reachable from the " + count(initial) +
                                        " initial pairs (x a family state, y each related "
                                        "reachable state; " +
                                        family_figure(c, m) + ")");
  r.figures.emplace_back("pairs", count(pairs.size()));
  r.figures.emplace_back("initial pairs", count(initial));
  r.figures.emplace_back("Reach", count(m.reach.store.size()));

  if (unmatched) {
    // The x-trace from its family state, then the step y cannot match; y's trace as a note.
    std::vector<StateId> path;
    for (StateId at = unmatched->first; at != checker::no_parent; at = parent[at])
      path.push_back(at);
    std::reverse(path.begin(), path.end());
    checker::Trace tx;
    std::vector<std::string> ysteps;
    tx.steps.push_back({"", 0, std::vector<Word>(pairs.state(path[0]), pairs.state(path[0]) + w)});
    for (std::size_t i = 1; i < path.size(); ++i) {
      const tioa::StepLabel& label = via[path[i]];
      tx.steps.push_back({gx.describe(label), tx.steps.back().time + gx.duration(label),
                          std::vector<Word>(pairs.state(path[i]), pairs.state(path[i]) + w)});
      ysteps.push_back(gy.describe(label));
    }
    const tioa::StepLabel& step = unmatched->second;
    tx.steps.push_back({gx.describe(step), tx.steps.back().time + gx.duration(step), unmatched_to});
    const checker::Trace to_y = checker::trace_to(gy, m.reach, origin[path[0]]);
    r.verdict = Verdict::violated;
    r.trace = std::move(tx);
    r.trace_role = "counterexample";
    r.trace_kind = "simulation-step";
    r.message =
        "the step " + gx.describe(step) + " from x after " + count(path.size() - 1) +
        " matched steps has no step of y with the same label to a related state (" +
        (unmatched_why.empty() ? std::string("y has no such step") : joined(unmatched_why, "; ")) +
        ")";
    r.notes.push_back("y: reached by " + actions_of(to_y) + "; then " +
                      (ysteps.empty() ? std::string("(no step)") : joined(ysteps)));
    return r;
  }
  if (stop != checker::StopReason::finished) {
    r.verdict = Verdict::incomplete;
    r.message = std::string(checker::describe(stop)) + " after " + count(pairs.size()) +
                " pairs: every step from the pairs expanded was matched";
    return r;
  }
  r.verdict = Verdict::holds;
  r.message = "every step and tick of x in each of the " + count(pairs.size()) +
              " pairs reachable from the initial pairs is matched by y with the same label to a "
              "related pair";
  const auto none = std::count_if(m.related.begin(), m.related.end(),
                                  [](const auto& related) { return related.empty(); });
  if (none > 0)
    r.notes.push_back(count(static_cast<std::uint64_t>(none)) +
                      " family states have no related reachable state (lemma-7.7): no pair "
                      "starts from them");
  return r;
}

PropertyResult check_lemma_7_6(const VlConfig& c, const tioa::Automaton& layer, MWindow window,
                               const checker::ExploreOptions& options) {
  return check_lemma_7_6(c, layer, window, options, RmcReading::loose);
}

} // namespace vlayer_mc
