#include "proofs/lemma_6_6.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "proofs/lemma_6_5.hpp"

namespace proofs {

namespace {

enum Claim66 { t_stab_window, total_rounds, lemma5, lemma5_step, lemma5_no_curve };

void evaluate_6_6(const FixpointInstance& instance, std::vector<std::optional<Measurement>>& out) {
  const mc::RoundSystem& system = instance.system;
  const mc::FixpointRun& run = instance.run;
  const int m = instance.setting.m;
  const std::int64_t m2 = m * m;
  const std::int64_t n = mc::total(instance.start);
  const mc::Rational& r3 = instance.rho3;
  const auto t_out = static_cast<std::int64_t>(run.t_out);
  const auto t_stab = static_cast<std::int64_t>(run.t_stab);

  const mc::Rational window_bound(numerator(r3) * (m2 * n), denominator(r3));
  mc::Rational total_bound = t_out_bound(instance);
  total_bound += window_bound;
  out[total_rounds] =
      Measurement{t_stab, total_bound,
                  "T_stab = " + std::to_string(run.t_stab) + ", n = " + std::to_string(n) +
                      ", rho3 = " + mc::to_string(r3)};
  out[t_stab_window] = Measurement{t_stab - t_out, window_bound,
                                   "T_stab - T_out = " + std::to_string(run.t_stab) + " - " +
                                       std::to_string(run.t_out) + ", rho3 = " + mc::to_string(r3) +
                                       ", n = " + std::to_string(n)};

  // |C_out| at T_out: the robots of Out(T_out), i.e. of the active regions off the curve.
  const Counts& at = run.rounds[run.t_out];
  const auto& q = system.q();
  const RobotCount k = system.params().k;
  RobotCount c_out = 0;
  for (std::size_t u = 0; u < at.size(); ++u)
    if (q[u] == 0)
      c_out += at[u];
  mc::Rational lemma5_bound = 10 * m2 * (2 * m - 1) / system.params().rho2;
  lemma5_bound += (k + 4) * (2 * m - 1) * m;
  // Without a curve nothing leaves Out: the proof's induction from the boundary has no base.
  const bool curve = std::any_of(q.begin(), q.end(), [](QuantisedLength l) { return l != 0; });
  out[curve ? lemma5 : lemma5_no_curve] = Measurement{
      c_out, lemma5_bound,
      "|C_out(T_out)| = " + std::to_string(c_out) + " at T_out = " + std::to_string(run.t_out)};

  // The proof's first step: a boundary VN g (q_g = 0 with a neighbour on the curve) keeps
  // (y_g − k)/|In_g| < 1, and |In_g| ≤ 4, so y_g < 4 + k.
  std::optional<RegionId> worst;
  for (RegionId g = 0; g < at.size(); ++g) {
    if (q[g] != 0 || at[g] == 0)
      continue;
    bool boundary = false;
    for (RegionId h : system.grid().nbrs(g))
      boundary = boundary || q[h] != 0;
    if (boundary && (!worst || at[g] > at[*worst]))
      worst = g;
  }
  if (worst) {
    std::size_t on_curve = 0;
    for (RegionId h : system.grid().nbrs(*worst))
      on_curve += q[h] != 0;
    out[lemma5_step] = Measurement{at[*worst], k + 3,
                                   "boundary region " + region_name(m, *worst) + " holds " +
                                       std::to_string(at[*worst]) + " robots at T_out, " +
                                       std::to_string(on_curve) + " neighbours on the curve"};
  }
}

} // namespace

const FixpointLemma& lemma_6_6() {
  static const FixpointLemma lemma{
      "lemma-6.6",
      "Lemma 6.6 of seed 000 (conference Lemmas 4 and 5 of seed 002): T_stab exists, the "
      "measured T_stab beside the journal's bound, and |C_out| beside the conference's bound "
      "(default order)",
      {
          {"6.6", "T_stab - T_out <= rho3 m^2 n (rho3 = q_max^2/((1-rho2)sigma), sigma = 1)",
           "seed 000 lines 1015, 1096; seed 002 line 286 (no bound)"},
          {"6.6 total",
           "T_stab <= 2m^2(1+rho3)m^2n^2 + (1+rho3)m^2n^2 + m^2n + rho3 m^2 n (Lemmas 6.2, 6.3, "
           "6.5, 6.6 chained, t0 = 0)",
           "seed 000 lines 1036, 1044, 1086, 1096"},
          {"L5", "|C_out(T_out)| <= (k+4)(2m-1)m + 10m^2(2m-1)/rho2",
           "seed 002 line 290 and the end of its proof (e for k); seed 000 line 1097 (O(m^3))"},
          {"L5 step",
           "at T_out every boundary Out region holds y_g < 4 + k robots (|In_g| <= 4 assumed)",
           "seed 002, proof of Lemma 5", false},
          {"L5 no curve",
           "|C_out(T_out)| <= (k+4)(2m-1)m + 10m^2(2m-1)/rho2 on grids without a curve (q = 0 "
           "everywhere: no boundary region, nothing ever leaves Out; outside the lemma's premise)",
           "seed 002 line 290", false},
      },
      evaluate_6_6,
  };
  return lemma;
}

FixpointCheck check_lemma_6_6(const Family& family, const CheckOptions& options) {
  return check_fixpoint_family(lemma_6_6(), family, options);
}

} // namespace proofs
