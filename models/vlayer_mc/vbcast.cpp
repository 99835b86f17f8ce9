#include "models/vlayer_mc/vbcast.hpp"

#include <algorithm>
#include <array>

#include "models/vlayer_mc/junk.hpp"
#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vbcast(const VlConfig& c) {
  const Lattice lattice = c.lattice();
  const int n = c.robots, points = lattice.points(), regions = lattice.regions(), d = c.d;
  tioa::Automaton a("VBcast");
  tioa::VariableArray<int> reg;
  for (int p = 0; p < n; ++p)
    reg.items.push_back(a.optional_integer("reg[" + std::to_string(p) + "]", 0, regions - 1));
  const auto cn_pending = a.booleans("cn_pending", n, false);
  const auto cn_age = a.clocks("cn_age", n, d, 0);
  const auto cn_loc = a.integers("cn_loc", n, 0, points - 1, 0);
  tioa::VariableArray<int> vn_mask;
  for (int u = 0; u < regions; ++u) {
    const int bits = static_cast<int>(lattice.nbrs(u).size());
    vn_mask.items.push_back(a.integer("vn_mask[" + std::to_string(u) + "]", 0, (1 << bits) - 1, 0));
  }
  const auto vn_age = a.clocks("vn_age", regions, d, 0);
  const auto vn_count = a.integers("vn_count", regions, 0, n, 0);
  const auto tu_pending = a.booleans("tu_pending", regions * n, false);
  const auto tu_age = a.clocks("tu_age", regions * n, d, 0);
  const auto tu_target = a.integers("tu_target", regions * n, 0, points - 1, 0);
  // D31: the junk a client's VBDelay hands over, slot j of client p at p·junk + j. `to` is
  // the mask of receivers still to get it (junk::receivers), `from` the sender's region.
  const int slots_per_client = c.junk, junk_slots = n * slots_per_client;
  const auto j_kind = a.integers("junk_kind", junk_slots, 0, junk::kinds - 1, junk::empty);
  const auto j_id = a.integers("junk_id", junk_slots, 0, junk::ids(c) - 1, 0);
  const auto j_value = a.integers("junk_value", junk_slots, 0, junk::values(c) - 1, 0);
  const auto j_from = a.integers("junk_from", junk_slots, 0, regions - 1, 0);
  const auto j_to = a.integers("junk_to", junk_slots, 0, (1 << regions) - 1, 0);
  const auto j_age = a.clocks("junk_age", junk_slots, d, 0);
  // Empties junk slot i once its last receiver got the message.
  const auto clear_junk = [=](State& s, int i) {
    s[j_kind[i]] = junk::empty;
    s[j_id[i]] = 0;
    s[j_value[i]] = 0;
    s[j_from[i]] = 0;
    s[j_to[i]] = 0;
    s[j_age[i]] = 0;
  };
  const auto junk_footprint = [=](tioa::Footprint& f) {
    for (int i = 0; i < junk_slots; ++i)
      f.reads(j_kind[i])
          .reads(j_id[i])
          .reads(j_value[i])
          .reads(j_from[i])
          .reads(j_to[i])
          .sets(j_kind[i], junk::empty) // a delivery only empties a slot (clear_junk)
          .sets(j_id[i], 0)
          .sets(j_value[i], 0)
          .sets(j_from[i], 0)
          .writes(j_to[i])
          .sets(j_age[i], 0);
  };

  for (int p = 0; p < n; ++p) {
    a.input(names::gps_update(p), {{"l", 0, points - 1}, {"t", 0, c.delta - 1}})
        .eff([=](State& s, const Params& x) { s[reg[p]] = lattice.region_of(x[0]); })
        .footprint(
            [=](const Params& x, tioa::Footprint& f) { f.sets(reg[p], lattice.region_of(x[0])); });
    a.input(names::vcast_prime_cn_update(p), {{"l", 0, points - 1}})
        .eff([=](State& s, const Params& x) {
          s[cn_pending[p]] =
              !s.is_bottom(reg[p]) && lattice.in_nbrs_plus(s[reg[p]], lattice.region_of(x[0]));
          s[cn_age[p]] = 0;
          s[cn_loc[p]] = x[0];
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.reads(reg[p]).writes(cn_pending[p]).sets(cn_age[p], 0).sets(cn_loc[p], x[0]);
        });
    if (c.junk > 0)
      a.input(names::vcast_prime_junk(p), {{"slot", 0, c.junk - 1},
                                           {"kind", 1, junk::kinds - 1},
                                           {"id", 0, junk::ids(c) - 1},
                                           {"value", 0, junk::values(c) - 1}})
          .eff([=](State& s, const Params& x) {
            const int i = p * slots_per_client + x[0];
            const auto region = [&](int q) -> std::optional<int> {
              if (q >= n || s.is_bottom(reg[q]))
                return std::nullopt;
              return s[reg[q]];
            };
            const std::optional<int> from = region(p);
            const int to = junk::receivers(lattice, n, x[1], x[2], x[3], from, region(x[2]));
            // D12 as for the other slots: a message into a slot with pending receivers
            // replaces it (only from arbitrary states of VBcast).
            clear_junk(s, i);
            if (to == 0)
              return;
            s[j_kind[i]] = x[1];
            s[j_id[i]] = x[2];
            s[j_value[i]] = x[3];
            s[j_from[i]] = *from;
            s[j_to[i]] = to;
          })
          .footprint([=](const Params& x, tioa::Footprint& f) {
            const int i = p * slots_per_client + x[0];
            for (const auto& r : reg.items)
              f.reads(r);
            f.writes(j_kind[i]).writes(j_id[i]).writes(j_value[i]).writes(j_from[i]);
            f.writes(j_to[i]).sets(j_age[i], 0);
          });
  }
  for (int u = 0; u < regions; ++u) {
    const auto& nbrs = lattice.nbrs(u);
    a.input(names::vcast_vn_update(u), {{"n", 0, n}})
        .eff([=](State& s, const Params& x) {
          s[vn_mask[u]] = (1 << nbrs.size()) - 1;
          s[vn_age[u]] = 0;
          s[vn_count[u]] = x[0];
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.sets(vn_mask[u], (1 << nbrs.size()) - 1).sets(vn_age[u], 0).sets(vn_count[u], x[0]);
        });
    a.input(names::vcast_target_update(u), {{"p", 0, n - 1}, {"x", 0, points - 1}})
        .eff([=](State& s, const Params& x) {
          const int slot = u * n + x[0];
          s[tu_pending[slot]] = !s.is_bottom(reg[x[0]]) && lattice.in_nbrs_plus(u, s[reg[x[0]]]);
          s[tu_age[slot]] = 0;
          s[tu_target[slot]] = x[1];
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          const int slot = u * n + x[0];
          f.reads(reg[x[0]]).writes(tu_pending[slot]).sets(tu_age[slot], 0);
          f.sets(tu_target[slot], x[1]);
        });
  }

  // Deliveries. A slot whose last receiver got the message is reset to age 0.
  //
  // D31: with junk slots the same message may be pending for the same receiver in several
  // slots (its own and junk ones). Each copy is a choice of the delivery (tioa's
  // `choose_where`): choice 0 the sender's own slot, choice 1 + i junk slot i, each a
  // step where its slot holds the message for this receiver. (Each choice reads only its
  // own slot, which the symbolic learner needs: counting the copies read every slot.)
  // Without junk slots the value a delivery carries is bound to its slot (tioa's `bind`).
  const auto junk_match = [=](const State& s, int i, int kind, int id, int value, int from,
                              int bit) {
    return s[j_kind[i]] == kind && s[j_id[i]] == id && s[j_value[i]] == value &&
           (from < 0 || s[j_from[i]] == from) && (s[j_to[i]] >> bit & 1) != 0;
  };
  // Delivers junk slot i's copy to the receiver `bit`.
  const auto take_junk = [=](State& s, int i, int bit) {
    s[j_to[i]] = s[j_to[i]] & ~(1 << bit);
    if (s[j_to[i]] == 0)
      clear_junk(s, i);
  };
  // The transition of delivery `b`: `own` is the copy in the sender's slot, `take_own`
  // delivers it, `junk_key` gives (kind, id, value, from, bit) of the junk copies, `bound`
  // binds parameter `param` when there are no junk slots.
  const auto deliver = [=](tioa::TransitionBuilder b, tioa::Guard own, tioa::Effect take_own,
                           auto junk_key, const std::string& param, tioa::Binder bound) {
    if (junk_slots == 0) {
      b.pre(own).bind(param, bound).eff(take_own);
      return;
    }
    b.choose_where(
        1 + static_cast<std::uint32_t>(junk_slots),
        [=](const State& s, const Params& x, std::uint32_t copy) {
          if (copy == 0)
            return own(s, x);
          const auto [kind, id, value, from, bit] = junk_key(x);
          return junk_match(s, static_cast<int>(copy) - 1, kind, id, value, from, bit);
        },
        [=](State& s, const Params& x, std::uint32_t copy) {
          if (copy == 0)
            take_own(s, x);
          else
            take_junk(s, static_cast<int>(copy) - 1, junk_key(x)[4]);
        });
  };
  using Key = std::array<int, 5>;
  for (int v = 0; v < regions; ++v) {
    deliver(
        a.output(names::vrcv_cn_update(v), {{"p", 0, n - 1}, {"l", 0, points - 1}})
            .footprint([=](const Params& x, tioa::Footprint& f) {
              f.reads(cn_pending[x[0]]).reads(cn_loc[x[0]]);
              f.sets(cn_pending[x[0]], false).sets(cn_age[x[0]], 0);
              junk_footprint(f);
            })
            .commutes_with_time(), // as the vn-update deliveries below
        [=](const State& s, const Params& x) {
          return s[cn_pending[x[0]]] && s[cn_loc[x[0]]] == x[1] && lattice.region_of(x[1]) == v;
        },
        [=](State& s, const Params& x) {
          s[cn_pending[x[0]]] = false;
          s[cn_age[x[0]]] = 0;
        },
        [=](const Params& x) {
          return Key{junk::cn_update, x[0], x[1], -1, v};
        },
        "l",
        [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
          return s[cn_loc[x[0]]];
        });
    deliver(
        a.output(names::vrcv_vn_update(v), {{"g", 0, regions - 1}, {"n", 0, n}})
            .footprint([=](const Params& x, tioa::Footprint& f) {
              f.reads(vn_mask[x[0]]).reads(vn_count[x[0]]);
              f.writes(vn_mask[x[0]]).sets(vn_age[x[0]], 0);
              junk_footprint(f);
            })
            // A delivery only clears a pending bit (and zeroes the age of a slot it
            // empties), and a slot's age advances only while it is pending: delivering
            // then ticking and ticking then delivering give the same state, the delivery
            // stays possible (its bit stays set) and clearing a bit never stops time.
            .commutes_with_time(),
        [=](const State& s, const Params& x) {
          const auto& from = lattice.nbrs(x[0]);
          const auto at = std::find(from.begin(), from.end(), v);
          return at != from.end() && (s[vn_mask[x[0]]] >> (at - from.begin()) & 1) != 0 &&
                 s[vn_count[x[0]]] == x[1];
        },
        [=](State& s, const Params& x) {
          const auto& from = lattice.nbrs(x[0]);
          const auto bit = std::find(from.begin(), from.end(), v) - from.begin();
          s[vn_mask[x[0]]] = s[vn_mask[x[0]]] & ~(1 << bit);
          if (s[vn_mask[x[0]]] == 0)
            s[vn_age[x[0]]] = 0;
        },
        [=](const Params& x) {
          return Key{junk::vn_update, x[0], x[1], -1, v};
        },
        "n",
        [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
          return s[vn_count[x[0]]];
        });
  }
  for (int p = 0; p < n; ++p)
    deliver(
        a.output(names::vrcv_target_update(p), {{"u", 0, regions - 1}, {"x", 0, points - 1}})
            .footprint([=](const Params& x, tioa::Footprint& f) {
              const int slot = x[0] * n + p;
              f.reads(tu_pending[slot]).reads(tu_target[slot]);
              f.sets(tu_pending[slot], false).sets(tu_age[slot], 0);
              junk_footprint(f);
            }),
        [=](const State& s, const Params& x) {
          const int slot = x[0] * n + p;
          return s[tu_pending[slot]] && s[tu_target[slot]] == x[1];
        },
        [=](State& s, const Params& x) {
          const int slot = x[0] * n + p;
          s[tu_pending[slot]] = false;
          s[tu_age[slot]] = 0;
        },
        [=](const Params& x) {
          return Key{junk::target_update, p, x[1], x[0], 0};
        },
        "x",
        [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
          return s[tu_target[x[0] * n + p]];
        });
  a.trajectories(
      [=](State& s) {
        for (int p = 0; p < n; ++p)
          if (s[cn_pending[p]])
            s.advance(cn_age[p]);
        for (int u = 0; u < regions; ++u)
          if (s[vn_mask[u]] != 0)
            s.advance(vn_age[u]);
        for (int slot = 0; slot < regions * n; ++slot)
          if (s[tu_pending[slot]])
            s.advance(tu_age[slot]);
        for (int i = 0; i < junk_slots; ++i)
          if (s[j_to[i]] != 0)
            s.advance(j_age[i]);
      },
      [=](const State& s) {
        for (int p = 0; p < n; ++p)
          if (s[cn_pending[p]] && s[cn_age[p]] >= d)
            return true;
        for (int u = 0; u < regions; ++u)
          if (s[vn_mask[u]] != 0 && s[vn_age[u]] >= d)
            return true;
        for (int slot = 0; slot < regions * n; ++slot)
          if (s[tu_pending[slot]] && s[tu_age[slot]] >= d)
            return true;
        for (int i = 0; i < junk_slots; ++i)
          if (s[j_to[i]] != 0 && s[j_age[i]] >= d)
            return true;
        return false;
      });
  return a;
}

} // namespace vlayer_mc
