#include "models/vn_layer/vlbcast.hpp"

#include <algorithm>

#include "models/vn_layer/names.hpp"
#include "models/vn_layer/round_tags.hpp"

namespace vn_layer {

using tioa::Params;
using tioa::State;

namespace {

// A client message in flight: ⟨kind, x_i, round⟩ from CN_i, for the VN of the zone of x_i
// (C15: the CN's zone at the send; a neighbour's VN would drop it, Fig. 3 lines 28, 32, 46).
struct ClientPlace {
  tioa::VariableArray<bool> pending;
  tioa::VariableArray<int> age, loc, round;
};

// What a step on CN_i's message in `place` reads and writes: the place's variables of i.
void touches(tioa::Footprint& f, const ClientPlace& place, int i) {
  f.reads(place.pending[i]).reads(place.loc[i]).reads(place.round[i]);
  f.writes(place.pending[i]).writes(place.age[i]).writes(place.loc[i]).writes(place.round[i]);
}

ClientPlace client_place(tioa::Automaton& a, const std::string& kind, int n, int points, int d_v) {
  return {a.booleans(kind + "_pending", n, false), a.clocks(kind + "_age", n, d_v, 0),
          a.integers(kind + "_loc", n, 0, points - 1, 0),
          a.integers(kind + "_round", n, 0, older_round, 0)};
}

} // namespace

tioa::Automaton vlbcast(const VnConfig& c) {
  const Lattice lattice = c.lattice();
  const int n = c.cns, points = lattice.points(), regions = lattice.regions(), d_v = c.d_v;
  tioa::Automaton a("VLBcast");
  const RoundClock clock(a, c.delta);
  const ClientPlace cn_update = client_place(a, "cn_update", n, points, d_v);
  const ClientPlace exchange = client_place(a, "exchange_trigger", n, points, d_v);
  const ClientPlace trigger = client_place(a, "target_trigger", n, points, d_v);
  // ⟨vn-update, h, n, round⟩ from VN_h, for the VNs of Nbrs_h (a bit each, in nbrs order).
  tioa::VariableArray<int> vn_mask;
  for (int h = 0; h < regions; ++h) {
    const int bits = static_cast<int>(lattice.nbrs(h).size());
    vn_mask.items.push_back(
        a.integer("vn_update_to[" + std::to_string(h) + "]", 0, (1 << bits) - 1, 0));
  }
  const auto vn_age = a.clocks("vn_update_age", regions, d_v, 0);
  const auto vn_count = a.integers("vn_update_n", regions, 0, n, 0);
  const auto vn_round = a.integers("vn_update_round", regions, 0, older_round, 0);
  // ⟨target-update, target⟩ from VN_h: the CNs with an entry (a bit each) and the entries.
  const auto tu_mask = a.integers("target_update_to", regions, 0, (1 << n) - 1, 0);
  const auto tu_age = a.clocks("target_update_age", regions, d_v, 0);
  const auto tu_target = a.integers("target_update_x", regions * n, 0, points - 1, 0);
  const auto overflow = a.boolean("overflow", false);

  const std::vector<std::pair<const ClientPlace*, std::string (*)(int)>> client_sends = {
      {&cn_update, names::send_cn_update},
      {&exchange, names::send_exchange_trigger},
      {&trigger, names::send_target_trigger}};
  const std::vector<std::pair<const ClientPlace*, std::string (*)(int)>> client_receives = {
      {&cn_update, names::receive_cn_update},
      {&exchange, names::receive_exchange_trigger},
      {&trigger, names::receive_target_trigger}};
  for (const auto& [place_pointer, send_name] : client_sends) {
    const ClientPlace place = *place_pointer;
    for (int i = 0; i < n; ++i)
      a.input(send_name(i), {{"loc", 0, points - 1}})
          .eff([=](State& s, const Params& m) {
            if (s[place.pending[i]])
              s[overflow] = true;
            s[place.pending[i]] = true;
            s[place.age[i]] = 0;
            s[place.loc[i]] = m[0];
            s[place.round[i]] = this_round; // the CN sends at the round it is in (Fig. 2)
          })
          .footprint([=](const Params&, tioa::Footprint& f) {
            touches(f, place, i);
            f.sets(overflow, true);
          });
  }
  for (const auto& [place_pointer, receive_name] : client_receives) {
    const ClientPlace place = *place_pointer;
    for (int h = 0; h < regions; ++h)
      a.output(receive_name(h),
               {{"i", 0, n - 1}, {"loc", 0, points - 1}, {"round", 0, older_round}})
          .pre([=](const State& s, const Params& m) {
            const int i = m[0];
            return s[place.pending[i]] && s[place.loc[i]] == m[1] && lattice.region_of(m[1]) == h &&
                   s[place.round[i]] == m[2];
          })
          .bind("loc",
                [=](const State& s, const Params& m) -> std::optional<std::int32_t> {
                  return s[place.loc[m[0]]];
                })
          .bind("round",
                [=](const State& s, const Params& m) -> std::optional<std::int32_t> {
                  return s[place.round[m[0]]];
                })
          .eff([=](State& s, const Params& m) {
            const int i = m[0];
            s[place.pending[i]] = false;
            s[place.age[i]] = 0;
            s[place.loc[i]] = 0;
            s[place.round[i]] = 0;
          })
          .footprint([=](const Params& m, tioa::Footprint& f) { touches(f, place, m[0]); });
  }

  for (int h = 0; h < regions; ++h) {
    const auto& nbrs = lattice.nbrs(h);
    const int everyone = (1 << nbrs.size()) - 1;
    a.input(names::send_vn_update(h), {{"n", 0, n}, {"round", 0, older_round}})
        .eff([=](State& s, const Params& m) {
          if (s[vn_mask[h]] != 0)
            s[overflow] = true;
          s[vn_mask[h]] = everyone;
          s[vn_age[h]] = 0;
          s[vn_count[h]] = m[0];
          s[vn_round[h]] = m[1];
        })
        .footprint([=](const Params& m, tioa::Footprint& f) {
          f.reads(vn_mask[h]).sets(vn_mask[h], everyone).sets(vn_age[h], 0);
          f.sets(vn_count[h], m[0]).sets(vn_round[h], m[1]).sets(overflow, true);
        });
    std::vector<tioa::ParamRange> entries;
    for (int i = 0; i < n; ++i)
      entries.push_back({"target_" + std::to_string(i), 0, points});
    a.input(names::send_target_update(h), entries)
        .eff([=](State& s, const Params& m) {
          if (s[tu_mask[h]] != 0)
            s[overflow] = true;
          int receivers = 0;
          for (int i = 0; i < n; ++i) {
            const bool entry = m[static_cast<std::size_t>(i)] != points; // null: no delivery (C1)
            receivers |= entry ? 1 << i : 0;
            s[tu_target[h * n + i]] = entry ? m[static_cast<std::size_t>(i)] : 0;
          }
          s[tu_mask[h]] = receivers;
          s[tu_age[h]] = 0;
        })
        .footprint([=](const Params&, tioa::Footprint& f) {
          f.reads(tu_mask[h]).writes(tu_mask[h]).sets(tu_age[h], 0).sets(overflow, true);
          for (int i = 0; i < n; ++i)
            f.writes(tu_target[h * n + i]);
        });
  }
  // receive(⟨vn-update, g, n, round⟩)_h from each neighbour g.
  for (int h = 0; h < regions; ++h)
    a.output(names::receive_vn_update(h),
             {{"g", 0, regions - 1}, {"n", 0, n}, {"round", 0, older_round}})
        .pre([=](const State& s, const Params& m) {
          const auto& from = lattice.nbrs(m[0]);
          const auto bit = std::find(from.begin(), from.end(), h);
          return bit != from.end() && (s[vn_mask[m[0]]] >> (bit - from.begin()) & 1) != 0 &&
                 s[vn_count[m[0]]] == m[1] && s[vn_round[m[0]]] == m[2];
        })
        .bind("n",
              [=](const State& s, const Params& m) -> std::optional<std::int32_t> {
                return s[vn_count[m[0]]];
              })
        .bind("round",
              [=](const State& s, const Params& m) -> std::optional<std::int32_t> {
                return s[vn_round[m[0]]];
              })
        .eff([=](State& s, const Params& m) {
          const int g = m[0];
          const auto& from = lattice.nbrs(g);
          const auto bit = std::find(from.begin(), from.end(), h) - from.begin();
          s[vn_mask[g]] = s[vn_mask[g]] & ~(1 << bit);
          if (s[vn_mask[g]] == 0) {
            s[vn_age[g]] = 0;
            s[vn_count[g]] = 0;
            s[vn_round[g]] = 0;
          }
        })
        .footprint([=](const Params& m, tioa::Footprint& f) {
          const int g = m[0];
          f.reads(vn_mask[g]).reads(vn_count[g]).reads(vn_round[g]).writes(vn_mask[g]);
          f.sets(vn_age[g], 0).sets(vn_count[g], 0).sets(vn_round[g], 0);
        });
  // receive(⟨target-update, target⟩)_i: CN_i's entry of VN_h's map.
  for (int i = 0; i < n; ++i)
    a.output(names::receive_target_update(i), {{"h", 0, regions - 1}, {"x", 0, points - 1}})
        .pre([=](const State& s, const Params& m) {
          return (s[tu_mask[m[0]]] >> i & 1) != 0 && s[tu_target[m[0] * n + i]] == m[1];
        })
        .bind("x",
              [=](const State& s, const Params& m) -> std::optional<std::int32_t> {
                return s[tu_target[m[0] * n + i]];
              })
        .eff([=](State& s, const Params& m) {
          const int h = m[0];
          s[tu_mask[h]] = s[tu_mask[h]] & ~(1 << i);
          s[tu_target[h * n + i]] = 0;
          if (s[tu_mask[h]] == 0)
            s[tu_age[h]] = 0;
        })
        .footprint([=](const Params& m, tioa::Footprint& f) {
          const int h = m[0];
          f.reads(tu_mask[h]).reads(tu_target[h * n + i]).writes(tu_mask[h]);
          f.sets(tu_target[h * n + i], 0).sets(tu_age[h], 0);
        });

  a.trajectories(
      [=](State& s) {
        const bool new_round = clock.tick(s);
        for (const ClientPlace* place : {&cn_update, &exchange, &trigger})
          for (int i = 0; i < n; ++i)
            if (s[place->pending[i]]) {
              s.advance(place->age[i]);
              if (new_round)
                s[place->round[i]] = aged(s[place->round[i]]);
            }
        for (int h = 0; h < regions; ++h) {
          if (s[vn_mask[h]] != 0) {
            s.advance(vn_age[h]);
            if (new_round)
              s[vn_round[h]] = aged(s[vn_round[h]]);
          }
          if (s[tu_mask[h]] != 0)
            s.advance(tu_age[h]);
        }
      },
      [=](const State& s) {
        for (const ClientPlace* place : {&cn_update, &exchange, &trigger})
          for (int i = 0; i < n; ++i)
            if (s[place->pending[i]] && s[place->age[i]] >= d_v)
              return true;
        for (int h = 0; h < regions; ++h)
          if ((s[vn_mask[h]] != 0 && s[vn_age[h]] >= d_v) ||
              (s[tu_mask[h]] != 0 && s[tu_age[h]] >= d_v))
            return true;
        return false;
      });
  return a;
}

} // namespace vn_layer
