#include "catalogue/token_ring.hpp"

#include <nlohmann/json.hpp>

#include "models/token_ring/token_ring.hpp"

namespace catalogue {

using tioa::State;

ModelInstance build_token_ring(int n, int k) {
  const token_ring::TokenRing ring = token_ring::build(n, k);
  const auto privileges = ring.privileges;
  auto exactly_one = [privileges](const State& s) { return privileges(s) == 1; };

  using checker::PropertyKind;
  ModelInstance m{ring.system, {}, ""};
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

// "privileged: P0, P3": the processes whose guard holds (Dijkstra's rule, as
// models/token_ring/token_ring.cpp writes it), read from a report's state.
std::string privileged_processes(const Json& params, const Json& state) {
  const int n = params.at("N").get<int>();
  const auto x = [&](int i) { return state.at("x[" + std::to_string(i) + "]").get<int>(); };
  std::string out;
  for (int i = 0; i < n; ++i)
    if (i == 0 ? x(0) == x(n - 1) : x(i) != x(i - 1))
      out += (out.empty() ? "" : ", ") + ("P" + std::to_string(i));
  return "privileged: " + (out.empty() ? std::string("none") : out);
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
  d.explain = privileged_processes;
  return d;
}

} // namespace catalogue
