#include "proofs/lemma_6_2.hpp"

#include <algorithm>
#include <string>

namespace proofs {

mc::Rational journal_window(const FixpointInstance& instance, int power) {
  const std::int64_t m2 = instance.setting.m * instance.setting.m;
  const std::int64_t n = mc::total(instance.start);
  mc::Rational window = 1 + instance.rho3;
  window *= m2 * (power == 2 ? n * n : n);
  return window;
}

bool same_in_out(const Counts& a, const Counts& b) {
  for (std::size_t u = 0; u < a.size(); ++u)
    if ((a[u] >= 1) != (b[u] >= 1))
      return false;
  return true;
}

bool keeps_sets(const FixpointInstance& instance, std::size_t t) {
  const auto& q = instance.system.q();
  const Counts& before = instance.run.rounds[t];
  const Counts& after = instance.run.rounds[t + 1];
  for (const mc::Transfer& move : instance.run.flows[t].transfers) {
    const bool from_in = q[move.from] != 0; // a sender has robots: it is active
    const bool to_out = q[move.to] == 0 && after[move.to] >= 1;
    if (from_in && !(q[move.to] != 0 && after[move.to] >= 1))
      return false; // (3): a robot of C_in(t) is not in C_in(t + 1)
    if (to_out && !(q[move.from] == 0 && before[move.from] >= 1))
      return false; // (4): a robot of C_out(t + 1) was not in C_out(t)
  }
  return true;
}

bool out_feeds_in(const FixpointInstance& instance, std::size_t t) {
  const auto& q = instance.system.q();
  const Counts& before = instance.run.rounds[t];
  for (const mc::Transfer& move : instance.run.flows[t].transfers)
    if (q[move.from] == 0 && q[move.to] != 0 && before[move.to] >= 1)
      return true;
  return false;
}

namespace {

// The last round of the window [start, start + length] that needs checking: rounds after the
// fixed point F repeat F.
std::size_t window_end(std::size_t start, const mc::Rational& length, std::size_t fixpoint) {
  const mc::BigInteger whole = numerator(length) / denominator(length); // length >= 0
  if (whole >= fixpoint)
    return fixpoint;
  return std::min(fixpoint, start + whole.convert_to<std::size_t>());
}

} // namespace

std::size_t measured_t1(const FixpointInstance& instance) {
  const mc::FixpointRun& run = instance.run;
  const std::size_t fixpoint = run.fixpoint_round;
  const mc::Rational window = journal_window(instance, 2);
  for (std::size_t t1 = 0; t1 < fixpoint; ++t1) {
    bool holds = true;
    const std::size_t end = window_end(t1, window, fixpoint);
    for (std::size_t t = t1; holds && t <= end; ++t)
      holds =
          same_in_out(run.rounds[t], run.rounds[t1]) && (t == fixpoint || keeps_sets(instance, t));
    if (holds)
      return t1;
  }
  return fixpoint;
}

namespace {

enum Claim62 { bound, changes };

void evaluate_6_2(const FixpointInstance& instance, std::vector<std::optional<Measurement>>& out) {
  const mc::FixpointRun& run = instance.run;
  const std::int64_t m2 = instance.setting.m * instance.setting.m;
  const std::size_t t1 = measured_t1(instance);
  mc::Rational t1_bound = journal_window(instance, 2);
  t1_bound *= 2 * m2;
  out[bound] = Measurement{static_cast<std::int64_t>(t1), t1_bound,
                           "t1 = " + std::to_string(t1) +
                               ", n = " + std::to_string(mc::total(instance.start)) +
                               ", rho3 = " + mc::to_string(instance.rho3)};

  std::int64_t changed = 0;
  std::string rounds;
  for (std::size_t t = 0; t < run.fixpoint_round; ++t)
    if (!same_in_out(run.rounds[t], run.rounds[t + 1])) {
      ++changed;
      rounds += (rounds.empty() ? "" : ", ") + std::to_string(t);
    }
  out[changes] = Measurement{changed, 2 * m2,
                             "In or Out changes in " + std::to_string(changed) + " rounds" +
                                 (rounds.empty() ? std::string() : " (" + rounds + ")")};
}

} // namespace

const FixpointLemma& lemma_6_2() {
  static const FixpointLemma lemma{
      "lemma-6.2",
      "Lemma 6.2 of seed 000 (no conference counterpart): In and Out become fixed at a round "
      "t1; the measured t1 beside the journal's bound (default order)",
      {
          {"6.2",
           "t1 <= t0 + 2m^2(1+rho3)m^2n^2, t0 = 0, t1 the least round such that In, Out stay "
           "as at t1 and C_in(t) ⊆ C_in(t+1), C_out(t+1) ⊆ C_out(t) for every t in [t1, "
           "t1 + (1+rho3)m^2n^2] (rho3 = q_max^2/((1-rho2)sigma), sigma = 1)",
           "seed 000 lines 1015, 1034-1036"},
          {"6.2 step", "In or Out changes in at most 2m^2 rounds (they only grow, Lemma 6.1)",
           "seed 000 line 1036 (the factor 2m^2)", false},
      },
      evaluate_6_2,
  };
  return lemma;
}

FixpointCheck check_lemma_6_2(const Family& family, const CheckOptions& options) {
  return check_fixpoint_family(lemma_6_2(), family, options);
}

} // namespace proofs
