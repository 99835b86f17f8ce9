#include "models/vn_layer/cn.hpp"

#include <algorithm>

#include "models/vn_layer/names.hpp"
#include "models/vn_layer/round_tags.hpp"

namespace vn_layer {

using tioa::Params;
using tioa::State;

tioa::Automaton cn(const VnConfig& c, int i) {
  const Lattice lattice = c.lattice();
  const int points = lattice.points();
  tioa::Automaton a("cn");
  const auto failed = a.boolean("failed", false);
  const RoundClock clock(a, c.delta);
  // Input x_i (Fig. 2 line 10): the CN's position, moved by its own velocity (C21).
  const auto x = a.integer("x", 0, points - 1, std::nullopt);
  const auto target = a.optional_integer("target", 0, points - 1); // x*, initially ⊥
  // round, next-exch, next-target ∈ N ∪ {⊥}, initially ⊥ (line 18), relative to the
  // current round ⌊realtime/δ⌋ (C23): a round number in the past can never equal
  // ⌈realtime/δ⌉ again, so all past ones are one value.
  const auto round = a.optional_integer("round", past_round, next_round);
  const auto next_exch = a.optional_integer("next_exch", past_round, next_round);
  const auto next_target = a.optional_integer("next_target", past_round, next_round);
  const auto zone = a.integer("zone", 0, lattice.regions() - 1, std::nullopt);
  const auto late_target_update = a.boolean("late_target_update", false);

  const int exchange_phase = c.exchange_phase(), target_phase = c.target_phase();
  const int reply_bound = c.d_mmt + 2 * c.d_v; // 002:160
  const auto due = [=](const State& s, tioa::Variable<int> counter, int phase) {
    return !s[failed] && s[clock.phase] == phase && !s.is_bottom(counter) &&
           s[counter] == this_round;
  };
  const auto moved_zone = [=](const State& s) {
    return !s[failed] && lattice.region_of(s[x]) != s[zone];
  };
  // The footprint of a send at the phase of `counter` (its guard `due` and its binder of x).
  const auto sends = [=](tioa::Footprint& f, tioa::Variable<int> counter) {
    f.reads(failed).reads(clock.phase).reads(counter).reads(x).sets(counter, next_round);
  };

  // Internal init_i (lines 20–26): round, next-exch, next-target ← ⌈realtime/δ⌉, x* ← x_i.
  a.internal(names::init(i))
      .pre([=](const State& s, const Params&) { return !s[failed] && s.is_bottom(round); })
      .eff([=](State& s, const Params&) {
        const int first = s[clock.phase] == 0 ? this_round : next_round;
        s[round] = first;
        s[next_exch] = first;
        s[next_target] = first;
        s[target] = s[x];
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(failed).reads(round).reads(clock.phase).reads(x);
        f.writes(round).writes(next_exch).writes(next_target).writes(target);
      });
  // Input receive(⟨target-update, target⟩)_i (lines 28–32): x* ← target(i). VLBcast hands
  // each CN its own entry only, and none where target(i) = null (C1).
  a.input(names::receive_target_update(i), {{"h", 0, lattice.regions() - 1}, {"x", 0, points - 1}})
      .eff([=](State& s, const Params& m) {
        if (s[failed]) // 001:36: only recover_i affects a failed CN
          return;
        s[target] = m[1];
        const int since_trigger = s[clock.phase] - target_phase;
        if (since_trigger < 0 || since_trigger > reply_bound)
          s[late_target_update] = true;
      })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.reads(failed).reads(clock.phase).sets(target, m[1]).sets(late_target_update, true);
      });
  // Output send(⟨cn-update, i, x_i, round⟩)_i (lines 34–38): realtime = round·δ.
  a.output(names::send_cn_update(i), {{"loc", 0, points - 1}})
      .pre([=](const State& s, const Params& m) { return due(s, round, 0) && m[0] == s[x]; })
      .bind("loc", x)
      .eff([=](State& s, const Params&) { s[round] = next_round; })
      .footprint([=](const Params&, tioa::Footprint& f) { sends(f, round); });
  // Output send(⟨exchange-trigger, x_i, next-exch⟩)_i (lines 40–44): realtime =
  // next-exch·δ + d_v + ε.
  a.output(names::send_exchange_trigger(i), {{"loc", 0, points - 1}})
      .pre([=](const State& s, const Params& m) {
        return due(s, next_exch, exchange_phase) && m[0] == s[x];
      })
      .bind("loc", x)
      .eff([=](State& s, const Params&) { s[next_exch] = next_round; })
      .footprint([=](const Params&, tioa::Footprint& f) { sends(f, next_exch); });
  // Output send(⟨target-trigger, x_i, next-target⟩)_i (lines 46–50): realtime =
  // next-target·δ + d_MMT + 3d_v + 2ε.
  a.output(names::send_target_trigger(i), {{"loc", 0, points - 1}})
      .pre([=](const State& s, const Params& m) {
        return due(s, next_target, target_phase) && m[0] == s[x];
      })
      .bind("loc", x)
      .eff([=](State& s, const Params&) { s[next_target] = next_round; })
      .footprint([=](const Params&, tioa::Footprint& f) { sends(f, next_target); });
  // Output enter_i(h): the zone CN_i stands in, for VLBcast's and the VN restarts' sake (C21).
  a.output(names::enter(i), {{"h", 0, lattice.regions() - 1}})
      .pre([=](const State& s, const Params& m) {
        return moved_zone(s) && m[0] == lattice.region_of(s[x]);
      })
      .bind("h",
            [=](const State& s, const Params&) -> std::optional<std::int32_t> {
              return lattice.region_of(s[x]);
            })
      .eff([=](State& s, const Params& m) { s[zone] = m[0]; })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.reads(failed).reads(x).reads(zone).sets(zone, m[0]);
      });

  // fail_i / recover_i (001:36, 002:35): inactive mode; seed 002 also sets the internal
  // variables to their initial values (C8: cn_fail=reset, the default).
  const bool reset = c.cn_fail == CnFail::reset;
  a.input(names::fail_cn(i)).eff([=](State& s, const Params&) {
    s[failed] = true;
    if (!reset)
      return;
    s.set_bottom(target);
    s.set_bottom(round);
    s.set_bottom(next_exch);
    s.set_bottom(next_target);
  });
  a.input(names::recover_cn(i)).eff([=](State& s, const Params&) { s[failed] = false; });

  // Trajectories (lines 52–56): v_i = v_c·(x* − x_i)/‖x* − x_i‖ unless x_i = x* or x* = ⊥
  // (C7: the figure's sign), as L∞ steps of v_c on the lattice (C29); a failed CN stands
  // still. Stop when round = ⊥ or realtime is one of the three send times (C30), or when
  // the CN has crossed into a zone it has not announced.
  const int vc = c.vc;
  a.trajectories(
      [=](State& s) {
        if (clock.tick(s))
          for (const auto counter : {round, next_exch, next_target})
            if (!s.is_bottom(counter))
              s[counter] = std::max(s[counter] - 1, past_round);
        if (!s[failed] && !s.is_bottom(target) && s[x] != s[target])
          s[x] = lattice.step_toward(s[x], s[target], vc);
      },
      [=](const State& s) {
        return (!s[failed] && s.is_bottom(round)) || due(s, round, 0) ||
               due(s, next_exch, exchange_phase) || due(s, next_target, target_phase) ||
               moved_zone(s);
      });
  return a;
}

} // namespace vn_layer
