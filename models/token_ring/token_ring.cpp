#include "models/token_ring/token_ring.hpp"

#include "tioa/operators.hpp"

namespace models {

using tioa::Params;
using tioa::State;

ModelInstance build_token_ring(int n, int k) {
  tioa::Automaton ring("token-ring");
  // State: x[0..N-1] in 0..K-1, nothing else; no initial values: U(A) starts anywhere.
  const auto x = ring.integers("x", static_cast<std::size_t>(n), 0, k - 1, std::nullopt);

  auto privileged = [x, n](const State& s, int i) {
    return i == 0 ? s[x[0]] == s[x[n - 1]] : s[x[i]] != s[x[i - 1]];
  };

  // Process 0: enabled iff x[0] == x[N-1]; x[0] := (x[0] + 1) mod K.
  // Process i >= 1: enabled iff x[i] != x[i-1]; x[i] := x[i-1].
  ring.internal("step", {{"i", 0, n - 1}})
      .pre([privileged](const State& s, const Params& a) { return privileged(s, a[0]); })
      .eff([x, k](State& s, const Params& a) {
        const int i = a[0];
        if (i == 0)
          s[x[0]] = (s[x[0]] + 1) % k;
        else
          s[x[i]] = s[x[i - 1]];
      });

  auto privileges = [privileged, n](const State& s) {
    int count = 0;
    for (int i = 0; i < n; ++i)
      count += privileged(s, i) ? 1 : 0;
    return count;
  };
  auto exactly_one = [privileges](const State& s) { return privileges(s) == 1; };

  using checker::PropertyKind;
  ModelInstance m{tioa::U(ring), {}, ""};
  m.properties = {
      {"some-privileged",
       "invariant: at least one process is privileged",
       PropertyKind::invariant,
       [privileges](const State& s) { return privileges(s) >= 1; },
       "at least one privileged",
       {},
       ""},
      {"legal-closure",
       "L = exactly one privileged is closed under every step",
       PropertyKind::legal_set,
       exactly_one,
       "exactly one privileged",
       {},
       ""},
      {"convergence",
       "every execution from U(A) reaches L = exactly one privileged",
       PropertyKind::stabilisation,
       exactly_one,
       "exactly one privileged",
       {},
       ""},
      {"transitivity",
       "Lemma 3.4 on two steps: U(A) -> at most two privileged -> exactly one privileged",
       PropertyKind::transitivity, exactly_one, "exactly one privileged",
       [privileges](const State& s) { return privileges(s) <= 2; }, "at most two privileged"},
  };
  return m;
}

ModelDefinition token_ring_definition() {
  ModelDefinition d;
  d.name = "token-ring";
  d.description = "Dijkstra's K-state self-stabilising token ring (time: steps)";
  d.params = {{"N", 5, 2, 20, "number of processes 0..N-1"},
              {"K", 4, 2, 64, "number of values of each x[i]"}};
  d.properties = {{"some-privileged", "invariant: at least one process is privileged"},
                  {"legal-closure", "L = exactly one privileged is a legal set (closure)"},
                  {"convergence", "U(A) stabilises to L; worst-case steps with a witness"},
                  {"transitivity", "Lemma 3.4 self-check via L1 = at most two privileged"}};
  d.check_params = [](const ParamValues& p) -> std::optional<std::string> {
    // K^N states must fit the 2^32 ids of the state store.
    double states = 1;
    for (int i = 0; i < p.at("N").integer(); ++i)
      states *= static_cast<double>(p.at("K").integer());
    if (states > 4e9)
      return "K^N = " + std::to_string(p.at("K").integer()) + "^" +
             std::to_string(p.at("N").integer()) +
             " states is more than the 2^32 the checker can store";
    return std::nullopt;
  };
  d.build = [](const ParamValues& p) {
    return build_token_ring(static_cast<int>(p.at("N").integer()),
                            static_cast<int>(p.at("K").integer()));
  };
  using checker::Verdict;
  d.suite = {{{{"N", 5}, {"K", 4}}, "some-privileged", Verdict::holds},
             {{{"N", 5}, {"K", 4}}, "legal-closure", Verdict::holds},
             {{{"N", 5}, {"K", 4}}, "convergence", Verdict::holds},
             {{{"N", 5}, {"K", 4}}, "transitivity", Verdict::holds},
             {{{"N", 5}, {"K", 3}}, "convergence", Verdict::violated},
             {{{"N", 7}, {"K", 6}}, "convergence", Verdict::holds}};
  return d;
}

} // namespace models
