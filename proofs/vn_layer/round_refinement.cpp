#include "proofs/vn_layer/round_refinement.hpp"

#include <cstdint>
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

namespace {

std::string counts_text(const std::vector<int>& counts) {
  std::string text = "(";
  for (std::size_t u = 0; u < counts.size(); ++u)
    text += (u ? ", " : "") + std::to_string(counts[u]);
  return text + ")";
}

// A round start whose counts are not the round-level system's.
struct Mismatch {
  StateId before, after;       // the two round starts
  std::vector<StateId> within; // the states between them, in order (before excluded)
  std::vector<int> found, expected, from;
};

} // namespace

checker::PropertyResult check_round_refinement(const VnConfig& c, const tioa::Automaton& system,
                                               const checker::ExploreOptions& options,
                                               bool cn_faults) {
  checker::PropertyResult r;
  r.name = "round-refinement";
  if (cn_faults) {
    r.kind = "round-refinement";
    r.verdict = checker::Verdict::incomplete;
    r.message = "not checked: with cn_faults=1 the active CNs change within a round, which no "
                "round-level system models";
    return r;
  }
  checker::require_exact_store(options, "round-refinement");
  const tioa::SuccessorGenerator gen(system);
  checker::ExploreHooks hooks;
  hooks.record_edges = true;
  const checker::Exploration ex = checker::explore(gen, system.start(), options, hooks);
  r = checker::result_of("round-refinement", ex, gen);
  r.name = "round-refinement";
  r.notes.push_back("the round-level system: at each round start, each zone's VN runs assign "
                    "(seed 002 Fig. 7, lower zones by increasing id, as the layer's VNs) on the "
                    "counts of that round start; its reassigned CNs count in the neighbour's "
                    "zone at the next round start, the others in their own; round 0 moves "
                    "nobody (C12)");
  note_round_rules(c, r);
  if (!ex.complete()) {
    checker::mark_incomplete(r, ex, "no round found to leave the round-level system so far");
    return r;
  }

  // From each round start, the states of its round are searched up to the round starts
  // that end it.
  const RoundView view(system, c);
  RoundWalker rounds(ex, view);
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
                  " round starts, every one of them followed by the round-level system";
      return r;
    }
    ++round_starts;
    const std::vector<int> from = view.counts(ex.store.state(start));
    // A start state and a later round start are told apart by how they were reached; one
    // state that is both is held to both.
    std::vector<std::vector<int>> allowed;
    if (start < ex.start_states)
      allowed.push_back(from);
    if (rounds.is_later_start(start))
      allowed.push_back(counts_after_round(c, from));
    rounds.walk(start, [&](StateId v, StateId to) {
      ++pairs;
      const std::vector<int> found = view.counts(ex.store.state(to));
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
    bool extended = true;
    for (const StateId w : mismatch->within)
      extended = extended && checker::extend(gen, trace, ex.store.state(w));
    extended = extended && checker::extend(gen, trace, ex.store.state(mismatch->after), 1u);
    if (!extended)
      throw std::logic_error("round-refinement: an edge of the graph is no step of the model");
    r.verdict = checker::Verdict::violated;
    r.trace = std::move(trace);
    r.trace_role = "counterexample";
    r.trace_kind = "round";
    r.message = "a round starts with the counts " + counts_text(mismatch->found) +
                " where the round-level system gives " + counts_text(mismatch->expected) +
                " from the counts " + counts_text(mismatch->from) +
                " at the round start before (trace: " + std::to_string(r.trace->length()) +
                " steps)";
    return r;
  }
  checker::mark_holds(r, ex,
                      "every round start reached has the counts the round-level system gives "
                      "from the round start before (" +
                          std::to_string(pairs) + " rounds from " + std::to_string(round_starts) +
                          " round starts), on all " + checker::reachable_states(n, ex));
  return r;
}

} // namespace vn_layer
