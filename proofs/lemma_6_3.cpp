#include "proofs/lemma_6_3.hpp"

#include <string>

namespace proofs {

std::size_t measured_t2(const FixpointInstance& instance, std::size_t t1) {
  const std::size_t fixpoint = instance.run.fixpoint_round;
  const mc::Rational window = journal_window(instance, 1);
  for (std::size_t t2 = t1; t2 < fixpoint; ++t2) {
    bool quiet = true;
    // Rounds t2 .. t2 + window, up to F − 1 (round F and later move nothing).
    for (std::size_t t = t2; quiet && t < fixpoint && t - t2 <= window; ++t)
      quiet = !out_feeds_in(instance, t);
    if (quiet)
      return t2;
  }
  return std::max(t1, fixpoint);
}

namespace {

enum Claim63 { after_t1, from_t0 };

void evaluate_6_3(const FixpointInstance& instance, std::vector<std::optional<Measurement>>& out) {
  const std::int64_t m2 = instance.setting.m * instance.setting.m;
  const std::size_t t1 = measured_t1(instance);
  const std::size_t t2 = measured_t2(instance, t1);
  const mc::Rational window = journal_window(instance, 2);
  const std::string detail = "t1 = " + std::to_string(t1) + ", t2 = " + std::to_string(t2) +
                             ", n = " + std::to_string(mc::total(instance.start)) +
                             ", rho3 = " + mc::to_string(instance.rho3);
  out[after_t1] = Measurement{static_cast<std::int64_t>(t2 - t1), window, detail};
  out[from_t0] = Measurement{static_cast<std::int64_t>(t2), window * (2 * m2 + 1), detail};
}

} // namespace

const FixpointLemma& lemma_6_3() {
  static const FixpointLemma lemma{
      "lemma-6.3",
      "Lemma 6.3 of seed 000 (no conference counterpart): the regions off the curve stop "
      "assigning robots to the curve at a round t2; the measured t2 beside the journal's bound "
      "(default order)",
      {
          {"6.3",
           "t2 - t1 <= (1+rho3)m^2n^2, t2 the least round >= t1 such that no region of Out(t) "
           "assigns robots to a neighbour in In(t) in any round t in [t2, t2 + (1+rho3)m^2n] "
           "(rho3 = q_max^2/((1-rho2)sigma), sigma = 1)",
           "seed 000 lines 1015, 1044-1045"},
          {"6.3 from t0",
           "t2 <= t0 + 2m^2(1+rho3)m^2n^2 + (1+rho3)m^2n^2, t0 = 0 (Lemmas 6.2 and 6.3 chained)",
           "seed 000 lines 1036, 1044"},
      },
      evaluate_6_3,
  };
  return lemma;
}

FixpointCheck check_lemma_6_3(const Family& family, const CheckOptions& options) {
  return check_fixpoint_family(lemma_6_3(), family, options);
}

} // namespace proofs
