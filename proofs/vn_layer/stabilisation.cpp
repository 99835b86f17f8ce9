#include "proofs/vn_layer/stabilisation.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/run_limits.hpp"
#include "checker/trace.hpp"
#include "models/vlayer_mc/targets.hpp"
#include "proofs/vn_layer/assignment_measures.hpp"
#include "proofs/vn_layer/layer_checks.hpp"
#include "proofs/vn_layer/round_graph.hpp"
#include "proofs/vn_layer/round_refinement.hpp"
#include "proofs/vn_layer/round_starts.hpp"

namespace vn_layer {

using checker::StateId;

namespace {

// What a round start says of the CNs: the point of each and its zone (the assignment the
// round before made; −1 for a failed CN), the zones restricted to those with q_h = 0 (−2
// elsewhere), and whether every active CN in a zone with q_h ≠ 0 stands on Γ_h.
struct RoundFacts {
  std::vector<std::vector<int>> points, zones, out_zones;
  std::vector<std::uint8_t> on_curve;
};

RoundFacts facts_of(const RoundGraph& g, const checker::Exploration& ex, const RoundView& view) {
  const auto q = vlayer_mc::curve_q(view.lattice);
  RoundFacts f;
  checker::StateReader read(ex);
  for (Node v = 0; v < g.size(); ++v) {
    const std::vector<int> points = view.points(read(g.state[v]));
    std::vector<int> zones = points, out = points; // −1 stays for a failed CN
    bool on = true;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (points[i] < 0)
        continue;
      zones[i] = out[i] = view.lattice.region_of(points[i]);
      if (q[static_cast<std::size_t>(zones[i])] != 0) {
        out[i] = -2;
        on = on && vlayer_mc::on_curve(view.lattice, zones[i], points[i]);
      }
    }
    f.points.push_back(points);
    f.zones.push_back(std::move(zones));
    f.out_zones.push_back(std::move(out));
    f.on_curve.push_back(on ? 1 : 0);
  }
  return f;
}

std::string rounds_text(std::uint32_t rounds) {
  return rounds == unbounded ? "unbounded" : std::to_string(rounds);
}

// The trace of a path of rounds (its first node a start state), each round's steps found
// again by searching it; `loop_node`: the index in `rounds` where a lasso's cycle begins
// (the last node equals it).
checker::Trace trace_of_rounds(const tioa::SuccessorGenerator& gen, const checker::Exploration& ex,
                               RoundWalker& walker, const RoundGraph& g,
                               const std::vector<Node>& rounds,
                               std::optional<std::size_t> loop_node) {
  checker::Trace trace = checker::trace_to(gen, ex, g.state[rounds.front()]);
  for (std::size_t i = 0; i + 1 < rounds.size(); ++i) {
    if (loop_node && *loop_node == i)
      trace.loop_start = trace.steps.size() - 1;
    const StateId from = g.state[rounds[i]], to = g.state[rounds[i + 1]];
    StateId last = checker::no_parent;
    walker.walk(from, [&](StateId v, StateId end) {
      if (end != to)
        return true;
      last = v;
      return false;
    });
    if (last == checker::no_parent)
      throw std::logic_error("stabilisation: a round of the graph was not found again");
    extend_by_round(gen, ex, trace, walker.path_within(from, last), to);
  }
  return trace;
}

} // namespace

std::uint32_t round_level_t_stab(const VnConfig& c, const std::vector<int>& start_counts) {
  // R_0 = the start counts, R_{j+1} the round-level system's from R_j, up to a repeat.
  std::vector<std::vector<int>> counts{start_counts};
  for (;;) {
    std::vector<int> after = counts_after_round(c, counts.back());
    const auto seen = std::find(counts.begin(), counts.end(), after);
    if (seen == counts.end() - 1) { // a fixed point from R_j on: the layer's round j + 1
      const auto j = static_cast<std::uint32_t>(counts.size() - 1);
      return j == 0 ? 0 : j + 1;
    }
    if (seen != counts.end())
      return unbounded; // a cycle of counts
    counts.push_back(std::move(after));
  }
}

checker::PropertyResult check_stabilisation(const VnConfig& c, const tioa::Automaton& system,
                                            const checker::ExploreOptions& options,
                                            bool cn_faults) {
  checker::PropertyResult r;
  r.name = "stabilisation";
  if (cn_faults) {
    r.kind = "stabilisation";
    r.verdict = checker::Verdict::incomplete;
    r.message = "not checked: Theorem 1 assumes no CN failure or recovery after round t_0, and "
                "with cn_faults=1 they may happen in any round";
    return r;
  }
  checker::require_stored_states(options, "stabilisation");
  const tioa::SuccessorGenerator gen(system);
  checker::ExploreHooks hooks;
  hooks.record_edges = true;
  const checker::Exploration ex = checker::explore(gen, system.start(), options, hooks);
  r = checker::result_of("stabilisation", ex, gen);
  r.name = "stabilisation";
  r.notes.push_back(
      "rounds are numbered as the CNs number them, from 0 at the start state; the VNs skip "
      "round 0 (C12), so a round-level round t is the layer's round t + 1");
  r.notes.push_back(
      "T_stab of an execution: the first round from which every CN stays in its zone at every "
      "round start (the set assigned to each VN no longer changes, 002:286); T_out the same for "
      "the CNs in zones with q_h = 0 (002:264); the theorem gives neither a bound (002:234)");
  r.notes.push_back(
      "C_in at round T_stab + 2 and later: every active CN in a zone with q_h != 0 (each such "
      "zone has held the same CNs for two rounds, so its VN is active, 002:230); on Gamma: on "
      "the closure of Gamma_h of its own zone h");
  r.notes.push_back(
      "proportionality (002:236, Lemma 6): at every round start from which the assignment may "
      "stay fixed for ever, over the zones In with q_h != 0 holding a CN; m = max(rows, cols); "
      "the exact bound, not its ceiling");
  r.notes.push_back(
      "even spacing in the limit (002:238, Lemma 7): measured, not judged, at the round starts "
      "on a cycle of rounds; the lattice rounds calctarget's points down, so a point may stop "
      "short of its place (the exact limit: mc-round lemma-6.8)");
  note_round_rules(c, r);
  if (!ex.complete()) {
    checker::mark_incomplete(r, ex, "no execution found that breaks Theorem 1 so far");
    return r;
  }

  const RoundView view(system, c);
  RoundWalker walker(ex, view);
  RoundGraph g;
  std::vector<Node> node_of(ex.store.size(), no_node);
  for (StateId v = 0; v < ex.store.size(); ++v)
    if (walker.is_round_start(v)) {
      node_of[v] = static_cast<Node>(g.state.size());
      g.state.push_back(v);
    }
  g.starts = static_cast<Node>(std::count_if(g.state.begin(), g.state.end(),
                                             [&](StateId v) { return v < ex.start_states; }));
  checker::PropertyLimitPoll poll(options.limits);
  std::uint64_t dead_ends = 0;
  const auto nodes = static_cast<Node>(g.state.size());
  for (Node v = 0; v < nodes; ++v) {
    if (poll.reached(v)) {
      r.verdict = checker::Verdict::incomplete;
      r.message = "stopped on a limit after the rounds of " + std::to_string(v) + " of " +
                  std::to_string(nodes) + " round starts";
      return r;
    }
    const std::size_t begin = g.next.size();
    walker.walk(g.state[v], [&](StateId, StateId to) {
      g.next.push_back(node_of[to]);
      return true;
    });
    std::sort(g.next.begin() + static_cast<std::ptrdiff_t>(begin), g.next.end());
    g.next.erase(std::unique(g.next.begin() + static_cast<std::ptrdiff_t>(begin), g.next.end()),
                 g.next.end());
    if (g.next.size() == begin)
      ++dead_ends;
    g.first.push_back(static_cast<std::uint32_t>(g.next.size()));
  }
  r.figures.emplace_back("round starts", std::to_string(g.size()));
  r.figures.emplace_back("rounds", std::to_string(g.next.size()));
  if (dead_ends) {
    r.verdict = checker::Verdict::incomplete;
    r.message = std::to_string(dead_ends) +
                " round starts have no next round (a time-lock: see no-timelock); the "
                "executions through them have no T_stab to measure";
    return r;
  }

  const RoundFacts facts = facts_of(g, ex, view);
  const Components comps = components_of(g);
  const auto moves = [&](Node v, Node w) { return facts.zones[v] != facts.zones[w]; };
  const auto out_moves = [&](Node v, Node w) { return facts.out_zones[v] != facts.out_zones[w]; };
  const auto no_node_event = [](Node) { return false; };
  const Settling stab = settling_of(g, comps, no_node_event, moves);
  const Settling out = settling_of(g, comps, no_node_event, out_moves);
  const Settling curve = settling_of(
      g, comps, [&](Node v) { return facts.on_curve[v] == 0; }, [](Node, Node) { return false; });
  const auto worst_over_starts = [&](const Settling& s) {
    std::uint32_t worst = 0;
    for (Node v = 0; v < g.starts; ++v)
      worst = std::max(worst, s.worst[v]);
    return worst;
  };
  r.figures.emplace_back("T_out (worst)", rounds_text(worst_over_starts(out)));
  r.figures.emplace_back("T_stab (worst)", rounds_text(worst_over_starts(stab)));
  r.figures.emplace_back("C_in on Gamma from round (worst)", rounds_text(worst_over_starts(curve)));

  // The round-level system from each start's counts (counts_after_round; the layer's
  // rounds 0 and 1 hold the start counts, C12): its T_stab in the layer's numbering, beside
  // the worst the layer shows from that start. The paper claims no equality; a difference
  // is a CN that changes zone where no count does (a swap) or the migration of V4.
  std::uint64_t equal = 0;
  std::int64_t widest = 0;
  checker::StateReader read(ex);
  for (Node v = 0; v < g.starts; ++v) {
    const std::uint32_t level = round_level_t_stab(c, view.counts(read(g.state[v])));
    if (level == stab.worst[v])
      ++equal;
    else if (level != unbounded && stab.worst[v] != unbounded)
      widest = std::max<std::int64_t>(widest, std::abs(static_cast<std::int64_t>(level) -
                                                       static_cast<std::int64_t>(stab.worst[v])));
  }
  r.figures.emplace_back("starts where T_stab = the round-level system's",
                         std::to_string(equal) + " of " + std::to_string(g.starts));
  if (equal < g.starts)
    r.notes.push_back("on " + std::to_string(g.starts - equal) +
                      " start states the worst T_stab differs from the round-level system's "
                      "(counts, the same start counts; by up to " +
                      std::to_string(widest) +
                      " rounds where both are finite): see round-refinement");

  // The round starts at or after T_stab on some execution: those from which an endless
  // path of rounds without a change begins.
  const std::vector<std::uint8_t> can_stay =
      endless_from(g, [&](Node v, Node w) { return !moves(v, w); });

  // Theorem 1(1)'s proportionality, Lemma 6 (002:236, 296–298), at each of them.
  const auto q = vlayer_mc::curve_q(view.lattice);
  const mc::Rational bound = proportionality_bound(c);
  mc::Rational widest_spread(0);
  Node spread_at = no_node; // the first (so nearest the start states) beyond the bound
  for (Node v = 0; v < g.size(); ++v) {
    if (!can_stay[v])
      continue;
    const mc::Rational spread = density_spread(view.counts(read(g.state[v])), q);
    widest_spread = std::max(widest_spread, spread);
    if (spread > bound && spread_at == no_node)
      spread_at = v;
  }
  r.figures.emplace_back("|y_h/q_h - y_g/q_g| from T_stab on (worst)",
                         mc::to_string(widest_spread) +
                             ", bound 10(2m-1)/(q_min rho2) = " + mc::to_string(bound));
  // No density exceeds cns/q_min, so a bound at or above it cannot be broken here.
  const mc::QuantisedLength q_min = q_min_of(q);
  if (mc::Rational(c.cns, q_min) <= bound)
    r.notes.push_back("proportionality cannot fail on this instance: every y_h/q_h is at most "
                      "cns/q_min = " +
                      mc::to_string(mc::Rational(c.cns, q_min)) +
                      ", within the bound; the measured spread says how far from it the "
                      "assignment is");

  // Lemma 7 (002:304–318), measured: the round starts an execution can visit for ever are
  // those on a cycle of rounds; there, each zone's distance to even spacing. Not judged:
  // the lattice rounds calctarget's points down (targets.hpp), so an interior CN stops once
  // ρ1 times its distance to its neighbours' midpoint is below one unit, and the exact
  // limit is checked at round level (mc-round lemma-6.8, theorem-6.9).
  const auto points_move = [&](Node v, Node w) { return facts.points[v] != facts.points[w]; };
  const Settling settle = settling_of(g, comps, no_node_event, points_move);
  SpacingGap widest_gap;
  for (Node v = 0; v < g.size(); ++v)
    if (comps.cyclic[comps.of[v]]) {
      SpacingGap gap = spacing_gap(c, view.lattice, facts.points[v]);
      if (gap.distance > widest_gap.distance)
        widest_gap = std::move(gap);
    }
  r.figures.emplace_back("CN points fixed from round (worst)",
                         rounds_text(worst_over_starts(settle)));
  r.figures.emplace_back("distance to even spacing in the limit (worst, lattice units)",
                         mc::to_string(widest_gap.distance) +
                             (widest_gap.where.empty() ? "" : " (" + widest_gap.where + ")"));
  if (settle.endless)
    r.notes.push_back("on some cycle of rounds the CNs' points keep changing: they do not "
                      "settle (Lemma 7's limit, 002:304, is not reached on the lattice)");

  // (1) The assignment becomes fixed on every execution.
  if (stab.endless) {
    const auto [from, to] = *stab.endless;
    std::vector<Node> rounds = path_from_start(g, from);
    const std::size_t loop = rounds.size() - 1;
    const auto inside = [&](Node a, Node b) { return comps.of[a] == comps.of[b]; };
    rounds.push_back(to);
    if (to != from)
      for (const Node w : path_between(g, to, from, inside))
        rounds.push_back(w);
    r.verdict = checker::Verdict::violated;
    r.trace = trace_of_rounds(gen, ex, walker, g, rounds, loop);
    r.trace_role = "counterexample";
    r.trace_kind = "lasso";
    r.message = "an execution on which CNs change zones in every cycle of " +
                std::to_string(rounds.size() - 1 - loop) +
                " rounds for ever: the assignment never becomes fixed (Theorem 1(1), "
                "002:234; trace: " +
                std::to_string(r.trace->length()) + " steps)";
    return r;
  }

  // (1) The fixed assignment is proportional to q within the bound: a round start beyond it
  // from which the assignment may stay fixed for ever breaks it.
  if (spread_at != no_node) {
    std::vector<Node> rounds = path_from_start(g, spread_at);
    const std::size_t at = rounds.size() - 1;
    const auto [after, loop] =
        cycle_from(g, spread_at, can_stay, [&](Node a, Node b) { return !moves(a, b); });
    rounds.insert(rounds.end(), after.begin(), after.end());
    r.verdict = checker::Verdict::violated;
    r.trace = trace_of_rounds(gen, ex, walker, g, rounds, at + loop);
    r.trace_role = "counterexample";
    r.trace_kind = "lasso";
    r.message =
        "an execution whose assignment stays fixed from round " + std::to_string(at) +
        " on with |y_h/q_h - y_g/q_g| = " +
        mc::to_string(density_spread(view.counts(read(g.state[spread_at])), q)) +
        " over In, beyond 10(2m-1)/(q_min rho2) = " + mc::to_string(bound) +
        " (Theorem 1(1), Lemma 6, 002:236, 298; trace: " + std::to_string(r.trace->length()) +
        " steps)";
    return r;
  }

  // (2) From round T_stab + 2 on, C_in on Γ (002:302). Rounds since the last change of
  // zones, up to 3 ("3 or more"), along every path; a node where the assignment may stay
  // fixed for ever (an endless path of rounds without a change) and a CN is off Γ at 2 or
  // more breaks the claim.
  const Node n = g.size();
  constexpr std::uint32_t levels = 4; // rounds since the last change: 0, 1, 2, 3 or more
  std::vector<std::uint32_t> parent(std::size_t{n} * levels, no_node);
  std::vector<std::uint32_t> queue;
  for (Node v = 0; v < g.starts; ++v) {
    parent[v * levels] = v * levels;
    queue.push_back(v * levels);
  }
  int latest_off = -1; // the largest level where a CN of C_in is off Γ and zones can stay
  std::uint32_t off_at = no_node; // the first (so nearest) at level 2 or more
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const Node v = queue[i] / levels;
    const std::uint32_t level = queue[i] % levels;
    if (!facts.on_curve[v] && can_stay[v]) {
      latest_off = std::max(latest_off, static_cast<int>(level));
      if (level >= 2 && off_at == no_node)
        off_at = queue[i];
    }
    g.for_arcs(v, [&](Node w) {
      const std::uint32_t to = w * levels + (moves(v, w) ? 0 : std::min(level + 1, levels - 1));
      if (parent[to] == no_node) {
        parent[to] = queue[i];
        queue.push_back(to);
      }
    });
  }
  r.figures.emplace_back("C_in on Gamma from, after T_stab (worst)",
                         latest_off < 0 ? "T_stab"
                         : latest_off + 1 < static_cast<int>(levels)
                             ? "T_stab + " + std::to_string(latest_off + 1)
                             : "T_stab + 4 or later");
  if (off_at != no_node) {
    const std::uint32_t off_level = off_at % levels;
    std::vector<Node> rounds;
    for (std::uint32_t p = off_at;; p = parent[p]) {
      rounds.push_back(p / levels);
      if (parent[p] == p)
        break;
    }
    std::reverse(rounds.begin(), rounds.end());
    const std::size_t off_round = rounds.size() - 1;
    const auto [after, loop] =
        cycle_from(g, rounds.back(), can_stay, [&](Node a, Node b) { return !moves(a, b); });
    rounds.insert(rounds.end(), after.begin(), after.end());
    r.verdict = checker::Verdict::violated;
    r.trace = trace_of_rounds(gen, ex, walker, g, rounds, off_round + loop);
    r.trace_role = "counterexample";
    r.trace_kind = "lasso";
    r.message = "an execution whose CNs stay in their zones from round " +
                std::to_string(off_round - std::min<std::size_t>(off_round, off_level)) +
                " on, with a CN of C_in off Gamma at the start of round " +
                std::to_string(off_round) + " (" + std::to_string(off_level) +
                (off_level == levels - 1 ? " or more" : "") +
                " rounds after T_stab; 002:302 has them on Gamma by T_stab + 2; trace: " +
                std::to_string(r.trace->length()) + " steps)";
    return r;
  }
  checker::mark_holds(r, ex,
                      "on every execution from every start state the assignment becomes fixed "
                      "(worst T_stab " +
                          rounds_text(worst_over_starts(stab)) +
                          ") within the proportionality bound of Lemma 6, and every CN of C_in "
                          "stands on Gamma from round T_stab + 2 on (" +
                          std::to_string(g.size()) + " round starts, " +
                          std::to_string(g.next.size()) + " rounds), on all " +
                          checker::reachable_states(ex.store.size(), ex));
  return r;
}

} // namespace vn_layer
