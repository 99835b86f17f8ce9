#include "proofs/lemma_6_5.hpp"

#include <string>
#include <vector>

namespace proofs {

mc::Rational t_out_bound(const FixpointInstance& instance) {
  // Lemma 6.2: t1 <= t0 + 2m²(1+ρ3)m²n²; Lemma 6.3: t2 <= t1 + (1+ρ3)m²n²; 6.5: + m²n.
  // = (1+ρ3)·m²n²(2m² + 1) + m²n, in as few rational operations as possible.
  const std::int64_t m2 = instance.setting.m * instance.setting.m;
  const std::int64_t n = mc::total(instance.start);
  mc::Rational bound = 1 + instance.rho3;
  bound *= m2 * n * n * (2 * m2 + 1);
  bound += m2 * n;
  return bound;
}

namespace {

enum Claim65 { chain, t_out_window };

void evaluate_6_5(const FixpointInstance& instance, std::vector<std::optional<Measurement>>& out) {
  const mc::RoundSystem& system = instance.system;
  const mc::FixpointRun& run = instance.run;
  const std::int64_t m2 = instance.setting.m * instance.setting.m;
  const std::int64_t n = mc::total(instance.start);

  out[chain] = Measurement{static_cast<std::int64_t>(run.t_out), t_out_bound(instance),
                           "T_out = " + std::to_string(run.t_out) + ", n = " + std::to_string(n) +
                               ", rho3 = " + mc::to_string(instance.rho3)};

  // t2 measured: the first round from which In and Out stay fixed and no Out region
  // assigns robots to an In neighbour (seed 000 Lemmas 6.2 (1)-(2), 6.3).
  std::size_t t2 = 0;
  const auto& q = system.q();
  for (std::size_t t = 0; t < run.fixpoint_round; ++t) {
    const Counts& before = run.rounds[t];
    const Counts& after = run.rounds[t + 1];
    bool moves = false;
    for (std::size_t u = 0; u < before.size(); ++u)
      moves = moves || ((before[u] >= 1) != (after[u] >= 1));
    for (const mc::Transfer& move : run.flows[t].transfers)
      moves = moves || (before[move.from] >= 1 && q[move.from] == 0 && before[move.to] >= 1 &&
                        q[move.to] != 0);
    if (moves)
      t2 = t + 1;
  }
  out[t_out_window] =
      Measurement{static_cast<std::int64_t>(run.t_out) - static_cast<std::int64_t>(t2), m2 * n,
                  "T_out - t2 = " + std::to_string(run.t_out) + " - " + std::to_string(t2) +
                      ", m^2 n = " + std::to_string(m2 * n)};
}

} // namespace

const FixpointLemma& lemma_6_5() {
  static const FixpointLemma lemma{
      "lemma-6.5",
      "Lemma 6.5 of seed 000 (conference Lemma 3 of seed 002): T_out exists; the measured T_out "
      "beside the journal's bound (default order)",
      {
          {"6.5",
           "T_out <= t0 + 2m^2(1+rho3)m^2n^2 + (1+rho3)m^2n^2 + m^2n, t0 = 0 (Lemmas 6.2, 6.3, 6.5 "
           "chained; rho3 = q_max^2/((1-rho2)sigma), sigma = 1)",
           "seed 000 lines 1015, 1036, 1044, 1086; seed 002 line 264 (no bound)"},
          {"6.5 window",
           "T_out - t2 <= m^2 n, t2 the first round from which In, Out stay fixed and no Out "
           "region assigns robots to an In neighbour (measured)",
           "seed 000 lines 1044-1045, 1086", false},
      },
      evaluate_6_5,
  };
  return lemma;
}

FixpointCheck check_lemma_6_5(const Family& family, const CheckOptions& options) {
  return check_fixpoint_family(lemma_6_5(), family, options);
}

} // namespace proofs
