#include "proofs/lemma_6_4.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

namespace proofs {

namespace {

enum ClaimIndex {
  conference_1,
  journal_1,
  conference_2,
  journal_2,
  step_1,
  step_2,
  sigma_as_stated,
  sigma_as_used,
};

using Wide = __int128;

// y_a/n_a < y_b/n_b, exactly (n > 0).
bool density_less(RobotCount ya, QuantisedLength na, RobotCount yb, QuantisedLength nb) {
  return Wide(ya) * nb < Wide(yb) * na;
}

std::string fraction(RobotCount y, QuantisedLength n) {
  return mc::to_string(mc::Rational(y, n));
}

// The inequalities of the lemma and its proof, multiplied out in integers of type Int.
// ρ2 = a/b; N = q_max; densities y/n (robots per σ).
template <class Int> struct Inequalities {
  Int a, b, N;

  // y_g'/n_g <= y_h/n_h − 1/N²  ⇔  y_g'·n_h·N² <= y_h·n_g·N² − n_g·n_h
  bool conference_gap(RobotCount yg1, QuantisedLength ng, RobotCount yh, QuantisedLength nh) const {
    return Int(yg1) * nh * N * N <= Int(yh) * ng * N * N - Int(ng) * nh;
  }
  // y_g'/n_g <= y_h/n_h − (1 − ρ2)/N²  ⇔  y_g'·n_h·N²·b <= y_h·n_g·N²·b − (b − a)·n_g·n_h
  bool journal_gap(RobotCount yg1, QuantisedLength ng, RobotCount yh, QuantisedLength nh) const {
    return Int(yg1) * nh * N * N * b <= Int(yh) * ng * N * N * b - (b - a) * ng * nh;
  }
  // y_g' <= ρ2·y_h + (1 − ρ2)·y_g  ⇔  b·y_g' <= a·y_h + (b − a)·y_g
  bool step_counts(RobotCount yg1, RobotCount yh, RobotCount yg) const {
    return b * yg1 <= a * yh + (b - a) * yg;
  }
  // y_g'/n_g <= (1 − ρ2)·y_g/n_g + ρ2·y_h/n_h  ⇔  b·y_g'·n_h <= (b − a)·y_g·n_h + a·y_h·n_g
  bool step_densities(RobotCount yg1, RobotCount yg, QuantisedLength ng, RobotCount yh,
                      QuantisedLength nh) const {
    return b * yg1 * nh <= (b - a) * yg * nh + a * yh * ng;
  }
  // |y_1/n_1 − y_2/n_2| >= 1/N²  ⇔  |y_1·n_2 − y_2·n_1|·N² >= n_1·n_2
  bool at_least_gap(RobotCount y1, QuantisedLength n1, RobotCount y2, QuantisedLength n2) const {
    Int difference = Int(y1) * n2 - Int(y2) * n1;
    if (difference < 0)
      difference = -difference;
    return difference * N * N >= Int(n1) * n2;
  }
};

// What g received and sent in the round, for the messages.
std::string traffic(int m, const mc::Flow& flow, RegionId g, const std::string& name = "g") {
  std::string in, out;
  for (const auto& t : flow.transfers) {
    if (t.to == g)
      in += (in.empty() ? "" : ", ") + std::to_string(t.robots) + " from " + region_name(m, t.from);
    if (t.from == g)
      out += (out.empty() ? "" : ", ") + std::to_string(t.robots) + " to " + region_name(m, t.to);
  }
  return name + " receives " + (in.empty() ? std::string("nothing") : in) + " and sends " +
         (out.empty() ? std::string("nothing") : out);
}

template <class Int>
void evaluate_with(const RoundStep& step, std::vector<ClaimOutcome>& out, const Int& a,
                   const Int& b) {
  const auto& system = step.system;
  const auto& grid = system.grid();
  const int m = grid.m();
  const auto& q = system.q();
  const auto& y = step.before;
  const auto& y1 = step.after;
  const std::size_t regions = y.size();
  const QuantisedLength q_max = *std::max_element(q.begin(), q.end());
  const Inequalities<Int> ineq{a, b, Int(q_max)};
  const mc::Rational& rho2 = system.params().rho2;

  auto active = [&](RegionId u) { return y[u] >= 1; };
  auto in_t = [&](RegionId u) { return active(u) && q[u] != 0; };
  auto out_t = [&](RegionId u) { return active(u) && q[u] == 0; };
  // The message is built only for the first failure of a claim in this round.
  auto fail = [&](ClaimIndex c, const auto& why) {
    if (!out[c].failure)
      out[c].failure = why();
  };

  // The window's round-local part: In and Out unchanged, no robot from off the curve onto it.
  bool window = true;
  for (RegionId u = 0; u < regions && window; ++u)
    window = (y[u] >= 1) == (y1[u] >= 1);
  for (const auto& t : step.flow.transfers)
    window = window && !(q[t.from] == 0 && q[t.to] != 0);

  for (RegionId g = 0; g < regions; ++g) {
    if (!active(g))
      continue;
    const auto& nbrs = grid.nbrs(g);

    if (q[g] == 0) { // part (1): g ∈ Out(t)
      RobotCount max_all = 0, max_out = 0;
      for (RegionId f : nbrs) {
        max_all = std::max(max_all, y[f]);
        if (out_t(f))
          max_out = std::max(max_out, y[f]);
      }
      for (RegionId h : nbrs) {
        if (!out_t(h) || !(y[g] < y[h]))
          continue;
        auto pair = [&] {
          return "g = " + region_name(m, g) + ", h = " + region_name(m, h) +
                 ": y_g(t) = " + std::to_string(y[g]) + " < y_h(t) = " + std::to_string(y[h]);
        };
        if (y[h] == max_all) {
          ++out[conference_1].premise;
          ++out[step_1].premise;
          if (!(y1[g] <= y[h] - 1))
            fail(conference_1, [&] {
              return pair() + " = max over Nbrs_g, but y_g(t+1) = " + std::to_string(y1[g]) +
                     " > y_h(t) - 1 = " + std::to_string(y[h] - 1) + " (" +
                     traffic(m, step.flow, g) + ")";
            });
          if (!ineq.step_counts(y1[g], y[h], y[g]))
            fail(step_1, [&] {
              return pair() + ", but y_g(t+1) = " + std::to_string(y1[g]) +
                     " > rho2*y_h + (1-rho2)*y_g = " +
                     mc::to_string(rho2 * y[h] + (1 - rho2) * y[g]) + " (" +
                     traffic(m, step.flow, g) + ")";
            });
        }
        if (window && y[h] == max_out) {
          ++out[journal_1].premise;
          if (!(y1[g] < y[h]))
            fail(journal_1, [&] {
              return "u = " + region_name(m, g) + ", v = " + region_name(m, h) +
                     ": y(u,t) = " + std::to_string(y[g]) + " < y(v,t) = " + std::to_string(y[h]) +
                     " = max over nbrs(u) and Out(t), but y(u,t+1) = " + std::to_string(y1[g]) +
                     " is not < " + std::to_string(y[h]) + " (" + traffic(m, step.flow, g, "u") +
                     ")";
            });
        }
      }
      continue;
    }

    // part (2): g ∈ In(t). The largest density among the neighbours on the curve (the
    // conference's max over Nbrs_g, where y/q is defined) and among those in In(t)
    // (the journal's); kept as (y, n).
    std::optional<std::pair<RobotCount, QuantisedLength>> max_curve, max_in;
    for (RegionId f : nbrs) {
      if (q[f] == 0)
        continue;
      if (!max_curve || density_less(max_curve->first, max_curve->second, y[f], q[f]))
        max_curve = {y[f], q[f]};
      if (in_t(f) && (!max_in || density_less(max_in->first, max_in->second, y[f], q[f])))
        max_in = {y[f], q[f]};
    }
    auto is_max = [&](const auto& best, RegionId h) {
      return best && !density_less(y[h], q[h], best->first, best->second);
    };
    for (RegionId h : nbrs) {
      if (!in_t(h))
        continue;
      // The simple calculation, as stated: a nonzero difference of densities is >= σ/q_max²
      // (every pair of neighbouring In(t) regions once).
      if (h > g && Wide(y[g]) * q[h] != Wide(y[h]) * q[g]) {
        ++out[sigma_as_stated].premise;
        if (!ineq.at_least_gap(y[h], q[h], y[g], q[g]))
          fail(sigma_as_stated, [&] {
            return "g = " + region_name(m, g) + ", h = " + region_name(m, h) + ": |" +
                   fraction(y[h], q[h]) + " - " + fraction(y[g], q[g]) + "| < 1/" +
                   std::to_string(q_max * q_max);
          });
      }
      if (!density_less(y[g], q[g], y[h], q[h]))
        continue;
      auto pair = [&] {
        return "g = " + region_name(m, g) + ", h = " + region_name(m, h) +
               ": y_g(t)/q_g = " + fraction(y[g], q[g]) + " < y_h(t)/q_h = " + fraction(y[h], q[h]);
      };
      auto after = [&] { return "y_g(t+1)/q_g = " + fraction(y1[g], q[g]); };
      if (is_max(max_curve, h)) {
        ++out[conference_2].premise;
        ++out[step_2].premise;
        if (!ineq.conference_gap(y1[g], q[g], y[h], q[h]))
          fail(conference_2, [&] {
            return pair() + " = max over Nbrs_g, but " + after() + " > y_h/q_h - sigma/q_max^2 = " +
                   mc::to_string(mc::Rational(y[h], q[h]) - mc::Rational(1, q_max * q_max)) +
                   " (q_max = " + std::to_string(q_max) + " sigma; " + traffic(m, step.flow, g) +
                   ")";
          });
        if (!ineq.step_densities(y1[g], y[g], q[g], y[h], q[h]))
          fail(step_2, [&] {
            return pair() + ", but " + after() + " > (1-rho2)*y_g/q_g + rho2*y_h/q_h = " +
                   mc::to_string((1 - rho2) * mc::Rational(y[g], q[g]) +
                                 rho2 * mc::Rational(y[h], q[h])) +
                   " (" + traffic(m, step.flow, g) + ")";
          });
        // The calculation as the proof uses it: from y_g(t+1)/q_g < y_h(t)/q_h to the gap.
        if (density_less(y1[g], q[g], y[h], q[h])) {
          ++out[sigma_as_used].premise;
          if (!ineq.at_least_gap(y[h], q[h], y1[g], q[g]))
            fail(sigma_as_used, [&] {
              return pair() + ": " + after() + " < y_h(t)/q_h but the gap is < 1/" +
                     std::to_string(q_max * q_max);
            });
        }
      }
      if (window && is_max(max_in, h)) {
        ++out[journal_2].premise;
        if (!ineq.journal_gap(y1[g], q[g], y[h], q[h]))
          fail(journal_2, [&] {
            return "u = " + region_name(m, g) + ", v = " + region_name(m, h) +
                   ": y(u,t)/q_u = " + fraction(y[g], q[g]) +
                   " < y(v,t)/q_v = " + fraction(y[h], q[h]) +
                   " = max over nbrs(u) and In(t), but y(u,t+1)/q_u = " + fraction(y1[g], q[g]) +
                   " > y(v,t)/q_v - (1-rho2)*sigma/q_max^2 = " +
                   mc::to_string(mc::Rational(y[h], q[h]) -
                                 (1 - rho2) * mc::Rational(1, q_max * q_max)) +
                   " (rho2 = " + mc::to_string(rho2) + ", q_max = " + std::to_string(q_max) +
                   " sigma; " + traffic(m, step.flow, g, "u") + ")";
          });
      }
    }
  }
}

void evaluate_6_4(const RoundStep& step, std::vector<ClaimOutcome>& out) {
  const mc::AssignParams& params = step.system.assign_params();
  // The widest product is y·n·q_max²·b (journal_gap). 128-bit integers when it stays below
  // 2^120 (counts < 2^40, q < 2^20, b < 2^20: every family and search here), 256-bit when
  // ρ2 fits in 64 bits (10^12·10^6·10^12·2^63 < 2^255), arbitrary precision otherwise.
  const auto& q = step.system.q();
  const RobotCount most = std::max(*std::max_element(step.before.begin(), step.before.end()),
                                   *std::max_element(step.after.begin(), step.after.end()));
  const QuantisedLength q_max = *std::max_element(q.begin(), q.end());
  if (params.small() && most < (RobotCount{1} << 40) && q_max < (1 << 20) &&
      params.rho2_denominator() < (1 << 20)) {
    evaluate_with<Wide>(step, out, Wide(params.rho2_numerator()), Wide(params.rho2_denominator()));
  } else if (params.small()) {
    using Int = boost::multiprecision::int256_t;
    evaluate_with<Int>(step, out, Int(params.rho2_numerator()), Int(params.rho2_denominator()));
  } else {
    const mc::Rational& rho2 = params.rho2();
    evaluate_with<mc::BigInteger>(step, out, boost::multiprecision::numerator(rho2),
                                  boost::multiprecision::denominator(rho2));
  }
}

} // namespace

std::optional<std::string> journal_window(const RoundStep& step) {
  const auto& system = step.system;
  const auto& q = system.q();
  const int m = system.grid().m();
  auto active_set = [](const Counts& counts) {
    std::vector<bool> active;
    for (RobotCount c : counts)
      active.push_back(c >= 1);
    return active;
  };
  const auto active = active_set(step.before);
  auto boundary_move = [&](const mc::Flow& flow) -> std::optional<std::string> {
    for (const auto& t : flow.transfers)
      if (q[t.from] == 0 && q[t.to] != 0)
        return std::to_string(t.robots) + " robot(s) from " + region_name(m, t.from) +
               " (Out) to " + region_name(m, t.to) + " (In)";
    return std::nullopt;
  };
  if (auto move = boundary_move(step.flow))
    return "round t moves " + *move + " (Lemma 6.3)";
  if (active_set(step.after) != active)
    return "In or Out changes in round t (Lemma 6.2)";
  mc::RunOptions options;
  options.max_rounds = 10'000;
  mc::FixpointRun run;
  try {
    run = system.run_to_fixpoint(step.after, options);
  } catch (const mc::RoundLimitReached&) {
    return "no fixed point within 10000 rounds after t";
  }
  for (std::size_t t = 0; t < run.flows.size(); ++t) {
    if (auto move = boundary_move(run.flows[t]))
      return "round t+" + std::to_string(t + 1) + " (default order) moves " + *move;
    if (active_set(run.rounds[t + 1]) != active)
      return "In or Out changes in round t+" + std::to_string(t + 1) + " (default order)";
  }
  return std::nullopt;
}

const RoundLemma& lemma_6_4() {
  static const RoundLemma lemma{
      "lemma-6.4",
      "Lemma 6.4 of seed 000 (conference Lemma 2 of seed 002): no region gets more robots (Out) "
      "or a higher density y/q (In) than its fullest neighbour had, one round t -> t+1",
      {
          {"L2(1)",
           "g, h in Out(t), h in Nbrs_g, y_h(t) = max over Nbrs_g of y_f(t), y_g(t) < y_h(t) => "
           "y_g(t+1) <= y_h(t) - 1 (every round t >= t0)",
           "seed 002 line 256"},
          {"6.4(1)",
           "u, v in Out(t), u in nbrs(v), y(v,t) = max over nbrs(u) and Out(t), y(u,t) < y(v,t) => "
           "y(u,t+1) < y(v,t) (rounds in the window t in [t2, ...])",
           "seed 000 lines 1059-1063", true, true},
          {"L2(2)",
           "g, h in In(t), h in Nbrs_g, y_h/q_h = max over Nbrs_g (on the curve) of y_f/q_f, "
           "y_g/q_g < y_h/q_h => y_g(t+1)/q_g <= y_h(t)/q_h - sigma/q_max^2 (every round t >= t0)",
           "seed 002 line 256"},
          {"6.4(2)",
           "u, v in In(t), u in nbrs(v), y(v,t)/q_v = max over nbrs(u) and In(t), "
           "y(u,t)/q_u < y(v,t)/q_v => y(u,t+1)/q_u <= y(v,t)/q_v - (1-rho2)*sigma/q_max^2 "
           "(rounds in the window t in [t2, ...])",
           "seed 000 lines 1065-1080", true, true},
          {"L2(1) step",
           "under L2(1)'s premise: each neighbour sends g at most rho2*(y_h-y_g)/4, all four at "
           "most rho2*(y_h-y_g), so y_g(t+1) <= rho2*y_h(t) + (1-rho2)*y_g(t)",
           "seed 002 line 258", false},
          {"L2(2) step",
           "under L2(2)'s premise: y_g(t+1)/q_g <= (1-rho2)*y_g(t)/q_g + rho2*y_h(t)/q_h",
           "seed 002 line 260", false},
          {"L2(2) sigma step (as stated)",
           "if y_h(t)/q_h != y_g(t)/q_g then their difference is at least sigma/q_max^2 (every "
           "pair of neighbouring In(t) regions)",
           "seed 002 line 260, 'a simple calculation'", false},
          {"L2(2) sigma step (as used)",
           "under L2(2)'s premise, if y_g(t+1)/q_g < y_h(t)/q_h then y_h(t)/q_h - y_g(t+1)/q_g >= "
           "sigma/q_max^2",
           "seed 002 line 260", false},
      },
      evaluate_6_4,
      // This journal_window, not Lemma 6.2's overload (a unity build sees both).
      [](const RoundStep& step) { return journal_window(step); },
  };
  return lemma;
}

LemmaCheck check_lemma_6_4(const Family& family, const CheckOptions& options) {
  return check_family(lemma_6_4(), family, options);
}

LemmaCheck search_lemma_6_4(const SearchOptions& options) {
  return search_random(lemma_6_4(), options);
}

} // namespace proofs
