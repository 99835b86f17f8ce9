#include "proofs/lemma_6_7.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace proofs {

namespace {

enum Claim67 { spread, step };

void evaluate_6_7(const FixpointInstance& instance, std::vector<std::optional<Measurement>>& out) {
  const mc::RoundSystem& system = instance.system;
  const Counts& fixed = instance.run.fixpoint();
  const auto& q = system.q();
  const int m = instance.setting.m;
  const std::vector<RegionId> in = system.in_regions(fixed);
  if (in.size() < 2)
    return;
  QuantisedLength q_min = 0;
  for (QuantisedLength length : q)
    if (length != 0 && (q_min == 0 || length < q_min))
      q_min = length;
  const mc::Rational& rho2 = system.params().rho2;
  auto density = [&](RegionId u) { return mc::Rational(fixed[u], q[u]); };

  // The largest difference over In is the largest density minus the smallest.
  // y_a/q_a < y_b/q_b, by cross-multiplying (small integers).
  auto less = [&](RegionId a, RegionId b) {
    return static_cast<std::int64_t>(fixed[a]) * q[b] < static_cast<std::int64_t>(fixed[b]) * q[a];
  };
  const auto [low, high] = std::minmax_element(in.begin(), in.end(), less);
  out[spread] =
      Measurement{density(*high) - density(*low), mc::Rational(10 * (2 * m - 1)) / (q_min * rho2),
                  "y/q = " + mc::to_string(density(*high)) + " at " + region_name(m, *high) + ", " +
                      mc::to_string(density(*low)) + " at " + region_name(m, *low) +
                      "; q_min = " + std::to_string(q_min)};

  // The neighbouring pair with the largest |y_u/q_u - y_v/q_v| = |y_u q_v - y_v q_u|/(q_u q_v).
  std::optional<std::pair<RegionId, RegionId>> worst;
  std::int64_t top = -1, bottom = 1;
  for (RegionId u : in)
    for (RegionId v : system.grid().nbrs(u))
      if (v > u && q[v] != 0 && fixed[v] >= 1) {
        std::int64_t gap =
            static_cast<std::int64_t>(fixed[u]) * q[v] - static_cast<std::int64_t>(fixed[v]) * q[u];
        gap = gap < 0 ? -gap : gap;
        const std::int64_t scale = static_cast<std::int64_t>(q[u]) * q[v];
        if (gap * bottom > top * scale) {
          top = gap;
          bottom = scale;
          worst = {u, v};
        }
      }
  if (worst)
    out[step] = Measurement{mc::Rational(top, bottom), mc::Rational(10) / (q_min * rho2),
                            "neighbours " + region_name(m, worst->first) +
                                " (y/q = " + mc::to_string(density(worst->first)) + ") and " +
                                region_name(m, worst->second) +
                                " (y/q = " + mc::to_string(density(worst->second)) + ")"};
}

} // namespace

const FixpointLemma& lemma_6_7() {
  static const FixpointLemma lemma{
      "lemma-6.7",
      "Lemma 6.7 of seed 000 (conference Lemma 6 of seed 002): proportionality at the fixed "
      "point, the measured worst |y_u/q_u - y_v/q_v| beside 10(2m-1)/(q_min rho2) (default "
      "order)",
      {
          {"6.7",
           "at every round t >= T_stab (the fixed point), for u, v in In: |y_u/q_u - y_v/q_v| "
           "<= 10(2m-1)/(q_min rho2)",
           "seed 000 line 1106; seed 002 line 296"},
          {"6.7 step",
           "for neighbouring u, v in In at the fixed point: |y_u/q_u - y_v/q_v| <= "
           "10/(q_min rho2) (|lower| <= 4 assumed)",
           "seed 002, proof of Lemma 6", false},
      },
      evaluate_6_7,
  };
  return lemma;
}

FixpointCheck check_lemma_6_7(const Family& family, const CheckOptions& options) {
  return check_fixpoint_family(lemma_6_7(), family, options);
}

} // namespace proofs
