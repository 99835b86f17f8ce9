#include "proofs/vn_layer/round_refinement.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "checker/explorer.hpp"
#include "checker/run_limits.hpp"
#include "checker/trace.hpp"
#include "models/mc/assign.hpp"
#include "models/vlayer_mc/targets.hpp"
#include "proofs/vn_layer/layer_checks.hpp"
#include "proofs/vn_layer/round_starts.hpp"

namespace vn_layer {

using checker::StateId;

std::vector<int> counts_after_round(const VnConfig& c, const std::vector<int>& counts) {
  const Lattice lattice = c.lattice();
  const auto q = vlayer_mc::curve_q(lattice);
  const mc::AssignParams params(c.k, c.rho2);
  std::vector<int> next = counts;
  for (RegionId h = 0; h < lattice.regions(); ++h) {
    // What VN_h knows when it computes (seed 002 Fig. 6 lines 46–52): its count and its
    // neighbours', each zone's q, as the round's cn-updates and vn-updates carry them.
    mc::VnView view;
    view.h = static_cast<mc::RegionId>(h);
    view.y = counts[static_cast<std::size_t>(h)];
    view.q = q[static_cast<std::size_t>(h)];
    const auto& nbrs = lattice.nbrs(h);
    for (const RegionId g : nbrs)
      view.neighbours.push_back({static_cast<mc::RegionId>(g), counts[static_cast<std::size_t>(g)],
                                 q[static_cast<std::size_t>(g)]});
    const mc::AssignResult plan = mc::assign(view, params);
    for (std::size_t i = 0; i < nbrs.size(); ++i) {
      next[static_cast<std::size_t>(h)] -= static_cast<int>(plan.sent[i]);
      next[static_cast<std::size_t>(nbrs[i])] += static_cast<int>(plan.sent[i]);
    }
  }
  return next;
}

std::vector<int> positions_after_round(const VnConfig& c, const std::vector<int>& positions) {
  const Lattice lattice = c.lattice();
  const vlayer_mc::VlConfig targets_config = c.targets_config();
  std::vector<int> counts(static_cast<std::size_t>(lattice.regions()), 0);
  for (const int p : positions)
    if (p >= 0)
      ++counts[static_cast<std::size_t>(lattice.region_of(p))];
  std::vector<int> next = positions;
  for (RegionId h = 0; h < lattice.regions(); ++h) {
    // VN_h's M: the CNs in its zone at the round start, at their points (their cn-updates,
    // Fig. 5 lines 34–38); V: its neighbours' counts (their vn-updates).
    std::vector<std::optional<Point>> reported(positions.size());
    bool anyone = false;
    for (std::size_t i = 0; i < positions.size(); ++i)
      if (positions[i] >= 0 && lattice.region_of(positions[i]) == h) {
        reported[i] = positions[i];
        anyone = true;
      }
    if (!anyone)
      continue;
    std::vector<int> nbr_counts;
    for (const RegionId g : lattice.nbrs(h))
      nbr_counts.push_back(counts[static_cast<std::size_t>(g)]);
    const auto targets = vlayer_mc::compute_targets(targets_config, h, reported, nbr_counts);
    for (std::size_t i = 0; i < positions.size(); ++i)
      if (reported[i] && targets[i])
        next[i] = *targets[i];
  }
  return next;
}

namespace {

std::string counts_text(const std::vector<int>& counts) {
  std::string text = "(";
  for (std::size_t u = 0; u < counts.size(); ++u)
    text += (u ? ", " : "") + std::to_string(counts[u]);
  return text + ")";
}

// One reading of the layer at its round starts and the round-level system that predicts it.
struct Reading {
  std::string property;  // its name
  std::string what;      // "counts", "points"
  std::string system;    // "the round-level system"
  std::string reference; // a note: what the system does
  std::function<std::vector<int>(const tioa::Word*)> read;
  std::function<std::vector<int>(const std::vector<int>&)> after_round;
  std::function<std::string(const std::vector<int>&)> text;
};

// A round start whose reading is not the round-level system's.
struct Mismatch {
  StateId before, after;       // the two round starts
  std::vector<StateId> within; // the states between them, in order (before excluded)
  std::vector<int> found, expected, from;
};

checker::PropertyResult check_reading(const VnConfig& c, const tioa::Automaton& system,
                                      const checker::ExploreOptions& options, bool cn_faults,
                                      const RoundView& view, const Reading& reading) {
  checker::PropertyResult r;
  r.name = reading.property;
  if (cn_faults) {
    r.kind = reading.property;
    r.verdict = checker::Verdict::incomplete;
    r.message = "not checked: with cn_faults=1 the active CNs change within a round, which no "
                "round-level system models";
    return r;
  }
  checker::require_stored_states(options, reading.property);
  const tioa::SuccessorGenerator gen(system);
  checker::ExploreHooks hooks;
  hooks.record_edges = true;
  const checker::Exploration ex = checker::explore(gen, system.start(), options, hooks);
  r = checker::result_of(reading.property, ex, gen);
  r.name = reading.property;
  r.notes.push_back(reading.reference);
  note_round_rules(c, r);
  if (!ex.complete()) {
    checker::mark_incomplete(r, ex, "no round found to leave " + reading.system + " so far");
    return r;
  }

  // From each round start, the states of its round are searched up to the round starts
  // that end it.
  RoundWalker rounds(ex, view);
  checker::StateReader read(ex);
  const std::uint64_t n = ex.store.size();
  std::uint64_t round_starts = 0, pairs = 0;
  checker::PropertyLimitPoll poll(options.limits);
  std::optional<Mismatch> mismatch;
  for (StateId start = 0; start < n && !mismatch; ++start) {
    if (!rounds.is_round_start(start))
      continue;
    if (poll.reached(round_starts)) {
      r.verdict = checker::Verdict::incomplete;
      r.message = "stopped on a limit after " + std::to_string(round_starts) +
                  " round starts, every one of them followed by " + reading.system;
      return r;
    }
    ++round_starts;
    const std::vector<int> from = reading.read(read(start));
    // A start state and a later round start are told apart by how they were reached; one
    // state that is both is held to both.
    std::vector<std::vector<int>> allowed;
    if (start < ex.start_states)
      allowed.push_back(from);
    if (rounds.is_later_start(start))
      allowed.push_back(reading.after_round(from));
    rounds.walk(start, [&](StateId v, StateId to) {
      ++pairs;
      const std::vector<int> found = reading.read(read(to));
      for (const std::vector<int>& expected : allowed)
        if (found != expected) {
          mismatch = Mismatch{start, to, rounds.path_within(start, v), found, expected, from};
          return false;
        }
      return true;
    });
  }
  r.figures.emplace_back("round starts", std::to_string(round_starts));
  r.figures.emplace_back("rounds checked", std::to_string(pairs));
  if (mismatch) {
    // A shortest path to the round start before, then the round's path to the mismatch
    // (each step an edge of the graph).
    checker::Trace trace = checker::trace_to(gen, ex, mismatch->before);
    extend_by_round(gen, ex, trace, mismatch->within, mismatch->after);
    r.verdict = checker::Verdict::violated;
    r.trace = std::move(trace);
    r.trace_role = "counterexample";
    r.trace_kind = "round";
    r.message = "a round starts with the " + reading.what + " " + reading.text(mismatch->found) +
                " where " + reading.system + " gives " + reading.text(mismatch->expected) +
                " from the " + reading.what + " " + reading.text(mismatch->from) +
                " at the round start before (trace: " + std::to_string(r.trace->length()) +
                " steps)";
    return r;
  }
  checker::mark_holds(r, ex,
                      "at every round start reached the " + reading.what + " are those " +
                          reading.system + " gives from the round start before (" +
                          std::to_string(pairs) + " rounds from " + std::to_string(round_starts) +
                          " round starts), on all " + checker::reachable_states(n, ex));
  return r;
}

} // namespace

checker::PropertyResult check_round_refinement(const VnConfig& c, const tioa::Automaton& system,
                                               const checker::ExploreOptions& options,
                                               bool cn_faults) {
  const RoundView view(system, c);
  Reading counts;
  counts.property = "round-refinement";
  counts.what = "counts";
  counts.system = "the round-level system";
  counts.reference = "the round-level system: at each round start, each zone's VN runs assign "
                     "(seed 002 Fig. 7, lower zones by increasing id, as the layer's VNs) on the "
                     "counts of that round start; its reassigned CNs count in the neighbour's "
                     "zone at the next round start, the others in their own; round 0 moves "
                     "nobody (C12)";
  counts.read = [&view](const tioa::Word* state) { return view.counts(state); };
  counts.after_round = [&c](const std::vector<int>& from) { return counts_after_round(c, from); };
  counts.text = counts_text;
  return check_reading(c, system, options, cn_faults, view, counts);
}

checker::PropertyResult check_position_refinement(const VnConfig& c, const tioa::Automaton& system,
                                                  const checker::ExploreOptions& options,
                                                  bool cn_faults) {
  const RoundView view(system, c);
  Reading points;
  points.property = "position-refinement";
  points.what = "points of the CNs";
  points.system = "the position-level round system";
  points.reference =
      "the position-level round system: at each round start, each zone's VN runs assign and "
      "calctarget (seed 002 Fig. 7, on the lattice as vlayer-mc's VN) on the points of the CNs "
      "in its zone and its neighbours' counts at that round start; every CN it computes for "
      "stands on its target at the next round start, a CN in a zone with no CN stays; round 0 "
      "moves nobody (C12)";
  points.read = [&view](const tioa::Word* state) { return view.points(state); };
  points.after_round = [&c](const std::vector<int>& from) {
    return positions_after_round(c, from);
  };
  const Lattice lattice = c.lattice();
  points.text = [lattice](const std::vector<int>& at) {
    std::string text = "(";
    for (std::size_t i = 0; i < at.size(); ++i) {
      text += i ? ", " : "";
      text += at[i] < 0 ? std::string("failed")
                        : "(" + std::to_string(lattice.x_of(at[i])) + ", " +
                              std::to_string(lattice.y_of(at[i])) + ")";
    }
    return text + ")";
  };
  return check_reading(c, system, options, cn_faults, view, points);
}

} // namespace vn_layer
