#include "models/fischer/fischer.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "tioa/ids_where.hpp"

namespace fischer {

using tioa::Params;
using tioa::State;

namespace {
enum class Loc { idle, req, wait, cs };
}

Fischer build(int n, int a, int b) {
  const int cmax = std::max(a, b) + 1;
  tioa::Automaton f("fischer");
  // State: shared id in 0..N (0 = free); per process p = 1..N a location and an integer
  // clock in 0..CMAX. One start state: id = 0, every loc[p] = IDLE, every c[p] = 0.
  const auto processes = tioa::ids(1, static_cast<std::size_t>(n));
  const auto id = f.integer("id", 0, n, 0);
  const auto loc = f.enumerations<Loc>("loc", processes, {"IDLE", "REQ", "WAIT", "CS"}, Loc::idle);
  const auto c = f.clocks("c", processes, cmax, 0);
  const tioa::ParamRange process{"p", 1, n};

  // | try   | loc[p] == IDLE && id == 0              | loc[p] := REQ;  c[p] := 0          |
  f.internal("try", {process})
      .where(process.name, loc, Loc::idle) // loc[p] == IDLE
      .pre([=](const State& s, const Params&) { return s[id] == 0; })
      .eff([=](State& s, const Params& x) {
        s[loc[x[0]]] = Loc::req;
        s[c[x[0]]] = 0;
      });
  // | set   | loc[p] == REQ                          | loc[p] := WAIT; id := p; c[p] := 0 |
  f.internal("set", {process})
      .where(process.name, loc, Loc::req) // loc[p] == REQ: the whole guard
      .eff([=](State& s, const Params& x) {
        s[loc[x[0]]] = Loc::wait;
        s[id] = x[0];
        s[c[x[0]]] = 0;
      });
  // | enter | loc[p] == WAIT && c[p] >= B && id == p | loc[p] := CS;   c[p] := 0          |
  f.internal("enter", {process})
      .pre([=](const State& s, const Params& x) {
        return s[loc[x[0]]] == Loc::wait && s[c[x[0]]] >= b && s[id] == x[0];
      })
      .bind(process.name, id) // only the process whose id is set may enter
      .eff([=](State& s, const Params& x) {
        s[loc[x[0]]] = Loc::cs;
        s[c[x[0]]] = 0;
      });
  // | fail  | loc[p] == WAIT && c[p] >= B && id != p | loc[p] := IDLE; c[p] := 0          |
  std::vector<int> clock_at_least_b; // the values B..CMAX a clock may hold with c[p] >= B
  for (int v = b; v <= cmax; ++v)
    clock_at_least_b.push_back(v);
  f.internal("fail", {process})
      .where(process.name, loc, Loc::wait)      // loc[p] == WAIT
      .where(process.name, c, clock_at_least_b) // c[p] >= B
      .pre([=](const State& s, const Params& x) { return s[id] != x[0]; })
      .eff([=](State& s, const Params& x) {
        s[loc[x[0]]] = Loc::idle;
        s[c[x[0]]] = 0;
      });
  // | exit  | loc[p] == CS                           | loc[p] := IDLE; id := 0            |
  f.internal("exit", {process})
      .where(process.name, loc, Loc::cs) // loc[p] == CS: the whole guard
      .eff([=](State& s, const Params& x) {
        s[loc[x[0]]] = Loc::idle;
        s[id] = 0;
      });

  // Time: a global tick, enabled iff no process is in REQ with c[p] >= A (urgency); it
  // advances the clocks of REQ and WAIT processes, saturating at CMAX.
  const tioa::IdsWhere<Loc> requesting(loc, {Loc::req});
  const tioa::IdsWhere<Loc> clocked(loc, {Loc::req, Loc::wait});
  f.trajectories([=](State& s) { clocked.for_each(s, [&](std::size_t p) { s.advance(c[p]); }); },
                 [=](const State& s) {
                   return requesting.any(s, [&](std::size_t p) { return s[c[p]] >= a; });
                 });

  const tioa::IdsWhere<Loc> in_cs(loc, {Loc::cs});
  const tioa::StatePredicate at_most_one_in_cs = [=](const State& s) {
    return in_cs.count(s) <= 1;
  };
  return {f, at_most_one_in_cs};
}

} // namespace fischer
