#include "models/vn_layer/vn.hpp"

#include <memory>

#include "models/vlayer_mc/target_memo.hpp"
#include "models/vn_layer/names.hpp"
#include "models/vn_layer/round_tags.hpp"

namespace vn_layer {

using tioa::Params;
using tioa::State;

std::vector<RegionId> v_zones(const Lattice& lattice, RegionId h) {
  std::vector<RegionId> zones = lattice.nbrs(h);
  zones.push_back(h);
  return zones;
}

namespace {

std::string at(const char* name, int index) {
  return std::string(name) + "[" + std::to_string(index) + "]";
}

} // namespace

tioa::Automaton vn(const VnConfig& c, RegionId h) {
  const Lattice lattice = c.lattice();
  const int n = c.cns, points = lattice.points();
  const std::vector<RegionId> zones = v_zones(lattice, h);
  const int own = static_cast<int>(zones.size()) - 1; // V's entry for h
  tioa::Automaton a("vn");
  const auto failed = a.boolean("failed", c.vns_start_failed);
  const RoundClock clock(a, c.delta);
  // M : I → B × N, initially ∅ (line 12).
  tioa::VariableArray<int> M, M_round;
  for (int i = 0; i < n; ++i) {
    M.items.push_back(a.optional_integer(at("M", i), 0, points - 1));
    M_round.items.push_back(a.integer(at("M_round", i), 0, older_round, 0));
  }
  // V : H → N × N, initially ⟨0, 0⟩ for each g ∈ Nbrs ∪ {h} (lines 14–16).
  tioa::VariableArray<int> V_num, V_round;
  for (std::size_t j = 0; j < zones.size(); ++j) {
    V_num.items.push_back(a.integer(at("V_num", zones[j]), 0, n, 0));
    V_round.items.push_back(a.integer(at("V_round", zones[j]), 0, older_round, 0));
  }
  // send-buffer, a queue, initially empty (line 18; C3: two places).
  std::vector<tioa::Variable<Buffered>> kind;
  tioa::VariableArray<int> count, count_round;
  std::vector<tioa::VariableArray<int>> map(buffer_slots);
  for (int slot = 0; slot < buffer_slots; ++slot) {
    kind.push_back(a.enumeration<Buffered>(at("buffer", slot),
                                           {"none", "vn-update", "target-update"}, Buffered::none));
    count.items.push_back(a.integer(at("buffer_count", slot), 0, n, 0));
    count_round.items.push_back(a.integer(at("buffer_round", slot), 0, older_round, 0));
    for (int i = 0; i < n; ++i)
      map[static_cast<std::size_t>(slot)].items.push_back(a.optional_integer(
          "buffer_target[" + std::to_string(slot) + "][" + std::to_string(i) + "]", 0, points - 1));
  }
  const auto task = a.clock("task", c.d_mmt, 0);
  const auto vn_done = a.integer("vn_done", 0, older_round, 0); // line 20, round 0
  const auto target_done = a.integer("target_done", 0, older_round, 0);
  // Observers (README "Observers"): the round of the exchange-trigger handled last, the y
  // of the last target computation and its round, and sticky flags.
  const auto exchanged = a.optional_integer("exchanged", 0, older_round);
  const auto y_round = a.optional_integer("y_round", 0, older_round);
  tioa::VariableArray<int> y;
  for (std::size_t j = 0; j < zones.size(); ++j)
    y.items.push_back(a.integer(at("y", zones[j]), 0, n, 0));
  const auto late_cn_update = a.boolean("late_cn_update", false);
  const auto late_vn_update = a.boolean("late_vn_update", false);
  const auto overflow = a.boolean("overflow", false);

  const auto size_of_M = [=](const State& s) {
    int size = 0;
    for (int i = 0; i < n; ++i)
      size += s.is_bottom(M[i]) ? 0 : 1;
    return size;
  };
  // send-buffer ∪ {m} appends (C3); a full buffer sets `overflow` (the model's bound).
  const auto free_slot = [=](State& s) -> int {
    for (int slot = 0; slot < buffer_slots; ++slot)
      if (s[kind[static_cast<std::size_t>(slot)]] == Buffered::none) {
        if (slot == 0)
          s[task] = 0; // the task becomes enabled
        return slot;
      }
    s[overflow] = true;
    return -1;
  };
  const auto pop = [=](State& s) {
    for (int slot = 0; slot + 1 < buffer_slots; ++slot) {
      s[kind[static_cast<std::size_t>(slot)]] = s[kind[static_cast<std::size_t>(slot + 1)]];
      s[count[slot]] = s[count[slot + 1]];
      s[count_round[slot]] = s[count_round[slot + 1]];
      for (int i = 0; i < n; ++i) {
        const auto& to = map[static_cast<std::size_t>(slot)][i];
        const auto& from = map[static_cast<std::size_t>(slot + 1)][i];
        if (s.is_bottom(from))
          s.set_bottom(to);
        else
          s[to] = s[from];
      }
    }
    const int last = buffer_slots - 1;
    s[kind[static_cast<std::size_t>(last)]] = Buffered::none;
    s[count[last]] = 0;
    s[count_round[last]] = 0;
    for (int i = 0; i < n; ++i)
      s.set_bottom(map[static_cast<std::size_t>(last)][i]);
    s[task] = 0; // the next message, if any, has d_MMT again
  };
  // The footprint of send(m)_h: its guard reads the head, pop moves every place up.
  const auto pops = [=](tioa::Footprint& f) {
    f.reads(failed).sets(task, 0);
    for (int slot = 0; slot < buffer_slots; ++slot) {
      const auto& targets = map[static_cast<std::size_t>(slot)];
      f.reads(kind[static_cast<std::size_t>(slot)]).writes(kind[static_cast<std::size_t>(slot)]);
      f.reads(count[slot]).writes(count[slot]).reads(count_round[slot]).writes(count_round[slot]);
      for (int i = 0; i < n; ++i)
        f.reads(targets[i]).writes(targets[i]);
    }
  };
  const auto reset = [=](State& s) { // "setting the automaton to an initial state"
    for (int i = 0; i < n; ++i) {
      s.set_bottom(M[i]);
      s[M_round[i]] = 0;
    }
    for (std::size_t j = 0; j < zones.size(); ++j) {
      s[V_num[j]] = 0;
      s[V_round[j]] = clock.round_zero(s);
    }
    for (int slot = 0; slot < buffer_slots; ++slot) {
      s[kind[static_cast<std::size_t>(slot)]] = Buffered::none;
      s[count[slot]] = 0;
      s[count_round[slot]] = 0;
      for (int i = 0; i < n; ++i)
        s.set_bottom(map[static_cast<std::size_t>(slot)][i]);
    }
    s[task] = 0;
    s[vn_done] = clock.round_zero(s);
    s[target_done] = clock.round_zero(s);
    s.set_bottom(exchanged);
    s.set_bottom(y_round);
    for (std::size_t j = 0; j < zones.size(); ++j)
      s[y[j]] = 0;
  };
  const auto in_zone = [=](int loc) { return lattice.region_of(loc) == h; };
  const int regions = lattice.regions();

  // Input receive(⟨cn-update, id, loc, round⟩)_h (lines 26–28): if loc ∈ B_h then
  // M(id) ← ⟨loc, round⟩ (C2: M is a map).
  a.input(names::receive_cn_update(h),
          {{"i", 0, n - 1}, {"loc", 0, points - 1}, {"round", 0, older_round}})
      .eff([=](State& s, const Params& m) {
        if (s[failed] || !in_zone(m[1]))
          return;
        s[M[m[0]]] = m[1];
        s[M_round[m[0]]] = m[2];
        if (!s.is_bottom(exchanged) && s[exchanged] == m[2])
          s[late_cn_update] = true; // (T1), 002:121
      })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.reads(failed).reads(exchanged).sets(M[m[0]], m[1]).sets(M_round[m[0]], m[2]);
        f.sets(late_cn_update, true);
      });
  // Input receive(⟨exchange-trigger, loc, round⟩)_h (lines 30–38).
  a.input(names::receive_exchange_trigger(h),
          {{"i", 0, n - 1}, {"loc", 0, points - 1}, {"round", 0, older_round}})
      .eff([=](State& s, const Params& m) {
        const int trigger_round = m[2];
        if (s[failed] || !in_zone(m[1]) || s[vn_done] == trigger_round)
          return;
        for (int i = 0; i < n; ++i)
          if (!s.is_bottom(M[i]) && s[M_round[i]] != trigger_round) {
            s.set_bottom(M[i]);
            s[M_round[i]] = 0;
          }
        const int slot = free_slot(s);
        if (slot >= 0) { // ⟨vn-update, h, |M|, round⟩ (C4: |M|, as 002:189 prints)
          s[kind[static_cast<std::size_t>(slot)]] = Buffered::vn_update;
          s[count[slot]] = size_of_M(s);
          s[count_round[slot]] = trigger_round;
        }
        s[vn_done] = trigger_round;
        s[exchanged] = trigger_round;
      });
  // Input receive(⟨vn-update, id, n, round⟩)_h (lines 40–42): if id ∈ Nbrs then
  // V(id) ← ⟨n, round⟩.
  a.input(names::receive_vn_update(h),
          {{"g", 0, regions - 1}, {"n", 0, n}, {"round", 0, older_round}})
      .eff([=](State& s, const Params& m) {
        if (s[failed])
          return;
        for (int j = 0; j < own; ++j)
          if (zones[static_cast<std::size_t>(j)] == m[0]) {
            s[V_num[j]] = m[1];
            s[V_round[j]] = m[2];
            if (!s.is_bottom(y_round) && s[y_round] == m[2])
              s[late_vn_update] = true; // (T2), 002:158
          }
      })
      .footprint([=](const Params& m, tioa::Footprint& f) {
        f.reads(failed).reads(y_round).sets(late_vn_update, true);
        for (int j = 0; j < own; ++j)
          if (zones[static_cast<std::size_t>(j)] == m[0])
            f.sets(V_num[j], m[1]).sets(V_round[j], m[2]);
      });
  // Input receive(⟨target-trigger, loc, round⟩)_h (lines 44–54).
  const auto memo = std::make_shared<const vlayer_mc::TargetMemo>(c.targets_config(), h);
  a.input(names::receive_target_trigger(h),
          {{"i", 0, n - 1}, {"loc", 0, points - 1}, {"round", 0, older_round}})
      .eff([=](State& s, const Params& m) {
        const int trigger_round = m[2];
        if (s[failed] || !in_zone(m[1]) || s[target_done] == trigger_round)
          return;
        s[V_num[own]] = size_of_M(s);
        s[V_round[own]] = trigger_round;
        for (int j = 0; j < own; ++j)
          if (s[V_round[j]] != trigger_round) {
            s[V_num[j]] = 0; // ⟨0, 0⟩: round 0
            s[V_round[j]] = clock.round_zero(s);
          }
        // calctarget(assign(id(M), y), locM), as vlayer-mc's VN computes it (C18, C19).
        thread_local std::vector<std::int32_t> key;
        key.clear();
        for (int i = 0; i < n; ++i)
          key.push_back(s.is_bottom(M[i]) ? vlayer_mc::TargetMemo::none : s[M[i]]);
        for (int j = 0; j < own; ++j)
          key.push_back(s[V_num[j]]);
        const std::int32_t* targets = memo->targets(key);
        const int slot = free_slot(s);
        if (slot >= 0) {
          s[kind[static_cast<std::size_t>(slot)]] = Buffered::target_update;
          for (int i = 0; i < n; ++i) {
            const auto& entry = map[static_cast<std::size_t>(slot)][i];
            if (targets[i] == vlayer_mc::TargetMemo::none)
              s.set_bottom(entry);
            else
              s[entry] = targets[i];
          }
        }
        s[target_done] = trigger_round;
        s[y_round] = trigger_round;
        for (std::size_t j = 0; j < zones.size(); ++j)
          s[y[j]] = s[V_num[j]];
      });
  // Output send(m)_h (lines 56–60), one action per kind of m: m = head(send-buffer).
  a.output(names::send_vn_update(h), {{"n", 0, n}, {"round", 0, older_round}})
      .pre([=](const State& s, const Params& m) {
        return !s[failed] && s[kind[0]] == Buffered::vn_update && s[count[0]] == m[0] &&
               s[count_round[0]] == m[1];
      })
      .bind("n", count[0])
      .bind("round", count_round[0])
      .eff([=](State& s, const Params&) { pop(s); })
      .footprint([=](const Params&, tioa::Footprint& f) { pops(f); });
  std::vector<tioa::ParamRange> entries;
  for (int i = 0; i < n; ++i) // a point, or `points` for null
    entries.push_back({"target_" + std::to_string(i), 0, points});
  tioa::TransitionBuilder send_targets = a.output(names::send_target_update(h), entries);
  send_targets
      .pre([=](const State& s, const Params& m) {
        if (s[failed] || s[kind[0]] != Buffered::target_update)
          return false;
        for (int i = 0; i < n; ++i) {
          const auto& entry = map[0][i];
          if (m[static_cast<std::size_t>(i)] != (s.is_bottom(entry) ? points : s[entry]))
            return false;
        }
        return true;
      })
      .eff([=](State& s, const Params&) { pop(s); })
      .footprint([=](const Params&, tioa::Footprint& f) { pops(f); });
  for (int i = 0; i < n; ++i)
    send_targets.bind("target_" + std::to_string(i),
                      [=](const State& s, const Params&) -> std::optional<std::int32_t> {
                        const auto& entry = map[0][i];
                        return s.is_bottom(entry) ? points : s[entry];
                      });

  // fail_h (001:38, 002:83): inactive, and set to an initial state; recover_h: active, with
  // all tasks restarted. Which zone may lose its VN, and when a VN recovers, is Zones'.
  a.input(names::fail_vn(h)).eff([=](State& s, const Params&) {
    s[failed] = true;
    reset(s);
  });
  a.input(names::recover_vn(h)).eff([=](State& s, const Params&) {
    if (!s[failed])
      return;
    s[failed] = false;
    s[task] = 0;
  });

  // No clock of its own (002:83): the phase only ages the round tags. The task {send(m)_h}
  // has bounds [0, d_MMT] (lines 62): time cannot pass once its message has waited d_MMT.
  const int d_mmt = c.d_mmt;
  a.trajectories(
      [=](State& s) {
        if (clock.tick(s)) {
          for (int i = 0; i < n; ++i)
            if (!s.is_bottom(M[i]))
              s[M_round[i]] = aged(s[M_round[i]]);
          for (std::size_t j = 0; j < zones.size(); ++j)
            s[V_round[j]] = aged(s[V_round[j]]);
          for (int slot = 0; slot < buffer_slots; ++slot)
            if (s[kind[static_cast<std::size_t>(slot)]] == Buffered::vn_update)
              s[count_round[slot]] = aged(s[count_round[slot]]);
          s[vn_done] = aged(s[vn_done]);
          s[target_done] = aged(s[target_done]);
          for (const auto tag : {exchanged, y_round})
            if (!s.is_bottom(tag))
              s[tag] = aged(s[tag]);
        }
        if (!s[failed] && s[kind[0]] != Buffered::none)
          s.advance(task);
      },
      [=](const State& s) {
        return !s[failed] && s[kind[0]] != Buffered::none && s[task] >= d_mmt;
      });
  return a;
}

} // namespace vn_layer
