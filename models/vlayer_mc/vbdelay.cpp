#include "models/vlayer_mc/vbdelay.hpp"

#include <algorithm>

#include "models/vlayer_mc/junk.hpp"
#include "models/vlayer_mc/names.hpp"

namespace vlayer_mc {

using tioa::Params;
using tioa::State;

tioa::Automaton vbdelay(const VlConfig& c, int p) {
  const int points = c.lattice().points(), e = c.e;
  tioa::Automaton a("delay");
  const auto held = a.boolean("held", false);
  const auto age = a.clock("age", std::max(e, 1), 0);
  const auto loc = a.integer("loc", 0, points - 1, 0);
  a.input(names::vcast_cn_update(p), {{"l", 0, points - 1}})
      .eff([=](State& s, const Params& x) {
        s[held] = true;
        s[age] = 0;
        s[loc] = x[0];
      })
      .footprint([=](const Params& x, tioa::Footprint& f) {
        f.sets(held, true).sets(age, 0).sets(loc, x[0]);
      });
  a.output(names::vcast_prime_cn_update(p), {{"l", 0, points - 1}})
      .pre([=](const State& s, const Params& x) { return s[held] && x[0] == s[loc]; })
      .bind("l", loc)
      .eff([=](State& s, const Params&) {
        s[held] = false;
        s[age] = 0;
      })
      .footprint([=](const Params&, tioa::Footprint& f) {
        f.reads(held).reads(loc).sets(held, false).sets(age, 0);
      });
  const int slots = c.junk;
  const auto kind = a.integers("junk_kind", slots, 0, junk::kinds - 1, junk::empty);
  const auto id = a.integers("junk_id", slots, 0, junk::ids(c) - 1, 0);
  const auto value = a.integers("junk_value", slots, 0, junk::values(c) - 1, 0);
  const auto junk_age = a.clocks("junk_age", slots, std::max(e, 1), 0);
  if (slots > 0)
    a.output(names::vcast_prime_junk(p), {{"slot", 0, slots - 1},
                                          {"kind", 1, junk::kinds - 1},
                                          {"id", 0, junk::ids(c) - 1},
                                          {"value", 0, junk::values(c) - 1}})
        .pre([=](const State& s, const Params& x) {
          return s[kind[x[0]]] == x[1] && s[id[x[0]]] == x[2] && s[value[x[0]]] == x[3];
        })
        .bind("kind",
              [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
                if (s[kind[x[0]]] == junk::empty)
                  return std::nullopt;
                return s[kind[x[0]]];
              })
        .bind("id",
              [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
                return s[id[x[0]]];
              })
        .bind("value",
              [=](const State& s, const Params& x) -> std::optional<std::int32_t> {
                return s[value[x[0]]];
              })
        .eff([=](State& s, const Params& x) {
          s[kind[x[0]]] = junk::empty;
          s[id[x[0]]] = 0;
          s[value[x[0]]] = 0;
          s[junk_age[x[0]]] = 0;
        })
        .footprint([=](const Params& x, tioa::Footprint& f) {
          f.reads(kind[x[0]]).reads(id[x[0]]).reads(value[x[0]]);
          f.sets(kind[x[0]], junk::empty).sets(id[x[0]], 0).sets(value[x[0]], 0);
          f.sets(junk_age[x[0]], 0);
        });
  a.trajectories(
      [=](State& s) {
        if (s[held])
          s.advance(age);
        for (int j = 0; j < slots; ++j)
          if (s[kind[j]] != junk::empty)
            s.advance(junk_age[j]);
      },
      [=](const State& s) {
        if (s[held] && s[age] >= e)
          return true;
        for (int j = 0; j < slots; ++j)
          if (s[kind[j]] != junk::empty && s[junk_age[j]] >= e)
            return true;
        return false;
      });
  return a;
}

} // namespace vlayer_mc
