#include "models/vlayer_mc/vn.hpp"

#include <algorithm>
#include <memory>

#include "models/vlayer_mc/names.hpp"
#include "models/vlayer_mc/target_memo.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vn(const VlConfig& c, RegionId u) {
  const Lattice lattice = c.lattice();
  const int n = c.robots, points = lattice.points(), regions = lattice.regions();
  const auto& nbrs = lattice.nbrs(u);
  tioa::Automaton a("vn");
  const auto clock = a.optional_integer("clock", 0, c.delta - 1);
  tioa::VariableArray<int> M, out;
  for (int p = 0; p < n; ++p)
    M.items.push_back(a.optional_integer("M[" + std::to_string(p) + "]", 0, points - 1));
  tioa::VariableArray<int> V;
  for (const RegionId g : nbrs)
    V.items.push_back(a.integer("V[" + std::to_string(g) + "]", 0, n, 0));
  for (int p = 0; p < n; ++p)
    out.items.push_back(a.optional_integer("out[" + std::to_string(p) + "]", 0, points - 1));
  const auto since = a.clock("since", 1, 1);
  const int vn_phase = c.vn_update_phase(), target_phase = c.target_phase();

  const auto at_phase = [=](const State& s, int phase) {
    return !s.is_bottom(clock) && s[clock] == phase && s[since] >= 1;
  };
  const auto reported = [=](const State& s) {
    int count = 0;
    for (int p = 0; p < n; ++p)
      count += s.is_bottom(M[p]) ? 0 : 1;
    return count;
  };
  const auto sending = [=](const State& s) {
    for (int p = 0; p < n; ++p)
      if (!s.is_bottom(out[p]))
        return true;
    return false;
  };

  // D26 (vn_repair) self-stabilisation: M_u holds reports only in the part of a round where
  // Def 7.1(2) (read with the window closed, F1) allows them, and only from a round the VSA
  // knew the time of: a time update that corrects the clock or comes after e + 2d + 2ε
  // empties M, and a cn-update that arrives after the vn-update (e + d + ε) is ignored. On
  // every state reachable without failures these are no-ops: the clock is right, cn-updates
  // arrive by e + d, and M is emptied at e + 2d + 2ε. The paper: the VSA records the time,
  // and collects a cn-update whenever it has a clock.
  const bool repair = c.vn_repair;
  const auto collecting = [=](int phase) { return !repair || phase <= vn_phase; };
  a.input(names::time(u), {{"t", 0, c.delta - 1}})
      .eff([=](State& s, const Params& m) {
        const bool reset =
            repair && ((!s.is_bottom(clock) && s[clock] != m[0]) || m[0] > target_phase);
        s[clock] = m[0];
        if (reset)
          for (int p = 0; p < n; ++p)
            s.set_bottom(M[p]);
      })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.sets(clock, m[0]);
        if (repair) {
          f.reads(clock);
          for (const auto& reports : M)
            f.sets_bottom(reports);
        }
      });
  tioa::TransitionBuilder cn_update =
      a.input(names::vrcv_cn_update(u), {{"p", 0, n - 1}, {"l", 0, points - 1}})
          .eff([=](State& s, const Params& m) {
            // D16: no clock, no round.
            if (!s.is_bottom(clock) && collecting(s[clock]) && lattice.region_of(m[1]) == u)
              s[M[m[0]]] = m[1];
          })
          .footprint(
              [=](const Params& m, tioa::Footprint& f) { f.reads(clock).sets(M[m[0]], m[1]); });
  // Time does not read M_u, and a tick keeps a clock (or its ⊥): the paper's VN takes a
  // report the same way a quantum later. D26 reads the phase, which a tick changes.
  if (!repair)
    cn_update.commutes_with_time();
  a.input(names::vrcv_vn_update(u), {{"g", 0, regions - 1}, {"n", 0, n}})
      .eff([=](State& s, const Params& m) {
        const auto at = std::find(nbrs.begin(), nbrs.end(), m[0]);
        if (at != nbrs.end())
          s[V.items[static_cast<std::size_t>(at - nbrs.begin())]] = m[1];
      })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        const auto at = std::find(nbrs.begin(), nbrs.end(), m[0]);
        if (at != nbrs.end())
          f.sets(V.items[static_cast<std::size_t>(at - nbrs.begin())], m[1]);
      })
      .commutes_with_time(); // V_u is not read by time: the clock and `since` are
  a.output(names::vcast_vn_update(u), {{"n", 0, n}})
      .pre([=](const State& s, const Params& m) {
        return at_phase(s, vn_phase) && m[0] == reported(s);
      })
      .bind(
          "n",
          [=](const State& s, const Params&) -> std::optional<std::int32_t> { return reported(s); })
      .eff([=](State& s, const Params&) { s[since] = 0; })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(clock).reads(since).sets(since, 0);
        for (const auto& m : M)
          f.reads(m);
      });
  const auto memo = std::make_shared<const TargetMemo>(c, u);
  a.internal("compute_" + std::to_string(u))
      .pre([=](const State& s, const Params&) { return at_phase(s, target_phase); })
      .eff([=](State& s, const Params&) {
        // The reports and counts as the memo's key, in a buffer each thread keeps.
        thread_local std::vector<std::int32_t> key;
        key.clear();
        for (int p = 0; p < n; ++p)
          key.push_back(s.is_bottom(M[p]) ? TargetMemo::none : s[M[p]]);
        for (const auto& count : V)
          key.push_back(s[count]);
        const std::int32_t* targets = memo->targets(key);
        for (int p = 0; p < n; ++p) {
          if (targets[p] != TargetMemo::none)
            s[out[p]] = targets[p];
          else
            s.set_bottom(out[p]);
          s.set_bottom(M[p]);
        }
        for (const auto& count : V)
          s[count] = 0;
        s[since] = 0;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(clock).reads(since).sets(since, 0);
        for (int p = 0; p < n; ++p)
          f.reads(M[p]).sets_bottom(M[p]).writes(out[p]);
        for (const auto& count : V)
          f.reads(count).sets(count, 0);
      });
  a.output(names::vcast_target_update(u), {{"p", 0, n - 1}, {"x", 0, points - 1}})
      .pre([=](const State& s, const Params& m) {
        return !s.is_bottom(out[m[0]]) && s[out[m[0]]] == m[1];
      })
      .bind("x",
            [=](const State& s, const Params& m) -> std::optional<std::int32_t> {
              if (s.is_bottom(out[m[0]]))
                return std::nullopt;
              return s[out[m[0]]];
            })
      .eff([=](State& s, const Params& m) { s.set_bottom(out[m[0]]); })
      .footprint(
          [=](const Params& m, tioa::Footprint& f) { f.reads(out[m[0]]).sets_bottom(out[m[0]]); });

  const int delta = c.delta;
  a.trajectories(
      [=](State& s) {
        if (!s.is_bottom(clock))
          s[clock] = (s[clock] + 1) % delta;
        s.advance(since);
      },
      [=](const State& s) {
        return at_phase(s, vn_phase) || at_phase(s, target_phase) || sending(s);
      });
  return a;
}

} // namespace vlayer_mc
