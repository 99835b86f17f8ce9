#include "proofs/lemma_6_8.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

#include "models/mc/spacing.hpp"
#include "proofs/witness_json.hpp"
#include "support/text.hpp"

namespace proofs {

namespace {

using Clock = std::chrono::steady_clock;
using mc::Rational;
using Vector = std::vector<Rational>;

using support::join;

std::string vector_text(const Vector& values) {
  std::vector<std::string> parts;
  for (const Rational& v : values)
    parts.push_back(mc::to_string(v));
  return "(" + join(parts) + ")";
}

std::string number(double value, const char* format = "%.6g") {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

enum ClaimId {
  matrix_radius,
  order,
  ends,
  linear_model,
  contraction,
  matrix_cross_check,
  contraction_ratio,
  printed_symmetric,
  printed_dynamics,
  printed_contracts,
  claim_count
};

Lemma68Tally make_claim(std::string id, std::string statement, std::string source,
                        bool decides_verdict = true) {
  return {.claim = {std::move(id), std::move(statement), std::move(source), decides_verdict}};
}

// A failing matrix claim: n interior robots (n + 2 with the ends) and ρ1.
Lemma68Counterexample matrix_example(const std::string& claim, std::size_t n, const Rational& rho1,
                                     std::string why) {
  Lemma68Counterexample example;
  example.claim = claim;
  example.robots = n + 2;
  example.rho1 = rho1;
  example.why = std::move(why);
  return example;
}

std::vector<Lemma68Tally> fresh_claims() {
  const std::string proof = "seed 002 lines 306-318";
  return {
      make_claim(
          "T: rho < 1",
          "the spectral radius of T (n x n, 1-rho1 on the diagonal, rho1/2 beside it) is < 1, "
          "decided exactly: every LDL^T pivot of I - T and I + T is > 0",
          "seed 002 line 318"),
      make_claim(
          "order",
          "calctarget keeps the robots' order: the parameters after a round are sorted (lines "
          "35-38 on a sorted seq)",
          "seed 002 line 210 (Fig. 7 lines 26-38); line 306"),
      make_claim("ends",
                 "after every round the first robot is at inf P_h = 0 and the last at sup P_h = L",
                 "seed 002 line 306 (Fig. 7 lines 35-36)"),
      make_claim(
          "linear model",
          "from round 1 on, the interior error e = p - even spacing satisfies e(k+1) = T e(k) "
          "exactly",
          "seed 002 lines 308, 312-314"),
      make_claim(
          "contraction",
          "from round 1 on, ||e(k+1)||^2 < ||e(k)||^2 exactly whenever e(k) != 0 (T symmetric, "
          "rho(T) < 1)",
          "seed 002 line 318"),
      make_claim("T: Eigen = closed form",
                 "Eigen's eigenvalues of T agree with 1 - rho1 + rho1 cos(j pi/(n+1)) within 1e-12 "
                 "(doubles; a cross-check of the construction)",
                 "tridiagonal Toeplitz spectrum", false),
      make_claim("contraction ratio (doubles)",
                 "from round 1 on, ||e(k+1)|| / ||e(k)|| <= rho(T_n) (1 + 1e-12), in doubles",
                 proof, false),
      make_claim("printed T: symmetric",
                 "the matrix as printed (last row 0 ... 0 0 1-rho1 rho1/2) is symmetric, as the "
                 "proof uses",
                 "seed 002 lines 316, 318", false),
      make_claim(
          "printed T: the dynamics",
          "from round 1 on, e(k+1) = T_printed e(k) exactly (the printed matrix as the model)",
          "seed 002 lines 314-316", false),
      make_claim("printed T: contracts",
                 "||T_printed x|| <= ||x|| for every x (what symmetry and rho < 1 give for the "
                 "intended T); "
                 "a failure is certified by an exact rational witness x",
                 "seed 002 lines 316-318", false),
  };
}

// Keeps the counterexample with fewer robots; ties keep the first.
void record_example(Lemma68Tally& tally, Lemma68Counterexample example) {
  ++tally.violations;
  tally.keep_smallest(std::move(example));
}

// T·x for the intended T, exactly.
Vector apply_intended(const Vector& x, const Rational& rho1) {
  const std::size_t n = x.size();
  const Rational diagonal = 1 - rho1, beside = rho1 / 2;
  Vector y(n);
  for (std::size_t i = 0; i < n; ++i) {
    Rational neighbours = 0;
    if (i > 0)
      neighbours += x[i - 1];
    if (i + 1 < n)
      neighbours += x[i + 1];
    y[i] = diagonal * x[i] + beside * neighbours;
  }
  return y;
}

// T_printed·x: the intended rows, then the printed last row (1-ρ1 at n-1, ρ1/2 at n).
Vector apply_printed(const Vector& x, const Rational& rho1) {
  Vector y = apply_intended(x, rho1);
  const std::size_t n = x.size();
  if (n >= 2)
    y[n - 1] = (1 - rho1) * x[n - 2] + rho1 / 2 * x[n - 1];
  return y;
}

Rational squared_norm(const Vector& x) {
  Rational sum = 0;
  for (const Rational& v : x)
    sum += v * v;
  return sum;
}

Eigen::MatrixXd dense(const std::vector<std::vector<Rational>>& matrix) {
  const auto n = static_cast<Eigen::Index>(matrix.size());
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      out(i, j) = matrix[i][j].convert_to<double>();
  return out;
}

// The tridiagonal matrix of doubles: diagonal a, beside b, the printed last row optionally.
Eigen::MatrixXd dense_t(std::size_t size, double rho1, bool printed) {
  const auto n = static_cast<Eigen::Index>(size);
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    t(i, i) = 1 - rho1;
    if (i > 0)
      t(i, i - 1) = rho1 / 2;
    if (i + 1 < n)
      t(i, i + 1) = rho1 / 2;
  }
  if (printed && n >= 2) {
    t(n - 1, n - 2) = 1 - rho1;
    t(n - 1, n - 1) = rho1 / 2;
  }
  return t;
}

// Eigen's symmetric tridiagonal QR on (diagonal, off-diagonal), eigenvalues ascending.
std::vector<double> tridiagonal_eigenvalues(const Eigen::VectorXd& diagonal,
                                            const Eigen::VectorXd& off) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("lemma 6.8: Eigen's tridiagonal QR did not converge");
  return {solver.eigenvalues().data(), solver.eigenvalues().data() + solver.eigenvalues().size()};
}

double spectral_radius(const std::vector<double>& eigenvalues) {
  double radius = 0;
  for (double value : eigenvalues)
    radius = std::max(radius, std::abs(value));
  return radius;
}

// ---- One unit of work: the matrices of one ρ1, or the starts of one (robots, L, ρ1)

struct Partial {
  std::vector<Lemma68Tally> claims = fresh_claims();
  // Matrices.
  std::uint64_t matrices = 0, printed_matrices = 0;
  double largest_radius = -1, largest_disagreement = 0;
  std::size_t largest_n = 0;
  Rational largest_rho1;
  double printed_radius = -1, printed_disagreement = 0, printed_norm = -1;
  std::size_t printed_radius_n = 0, printed_norm_n = 0;
  Rational printed_radius_rho1, printed_norm_rho1;
  std::optional<SlowestRate> slowest;
  // Dynamics.
  std::uint64_t starts = 0, grid_starts = 0, rounds = 0, model_rounds = 0;
  std::uint64_t first_round_growth = 0, reached_even = 0;
  double final_error = 0, ratio = 0, ratio_over_rho = 0;
};

void check_matrices(const Lemma68Family& family, const Rational& rho1, Partial& out) {
  const double r = rho1.convert_to<double>();
  const std::size_t big = family.max_interior;
  const std::size_t certified = certified_up_to(big, rho1);
  for (std::size_t n = 1; n <= big; ++n) {
    ++out.matrices;
    Lemma68Tally& radius = out.claims[matrix_radius];
    ++radius.premise;
    if (n > certified)
      record_example(radius, matrix_example(radius.claim.id, n, rho1,
                                            "an LDL^T pivot of I - T or I + T is <= 0 at size " +
                                                std::to_string(certified + 1) +
                                                ", so rho(T) >= 1 for n = " + std::to_string(n)));

    const Eigen::MatrixXd t = dense_t(n, r, false);
    if (!t.isApprox(t.transpose(), 0.0))
      throw std::logic_error("lemma 6.8: the intended T is not symmetric");
    const std::vector<double> eigen = tridiagonal_eigenvalues(t.diagonal(), t.diagonal(1));
    const std::vector<double> closed = closed_form_eigenvalues(n, r);
    double disagreement = 0;
    for (std::size_t j = 0; j < n; ++j)
      disagreement = std::max(disagreement, std::abs(eigen[j] - closed[j]));
    out.largest_disagreement = std::max(out.largest_disagreement, disagreement);
    Lemma68Tally& cross = out.claims[matrix_cross_check];
    ++cross.premise;
    if (!(disagreement <= 1e-12))
      record_example(cross,
                     matrix_example(cross.claim.id, n, rho1,
                                    "largest |Eigen - closed form| = " + number(disagreement)));
    const double rho = spectral_radius(eigen);
    if (rho > out.largest_radius) {
      out.largest_radius = rho;
      out.largest_n = n;
      out.largest_rho1 = rho1;
    }
    if (n == big) {
      // 1 − λ_max = ρ1(1 − cos(π/(n+1))) = 2ρ1 sin²(π/(2(n+1))), without cancellation.
      const double s = std::sin(std::numbers::pi / (2.0 * static_cast<double>(n + 1)));
      const double m = static_cast<double>(n + 1);
      // ρ(T) = max(λ_max, |λ_min|) by the closed form; λ_max ≥ |λ_min| when ρ1 ≤ 1.
      const double lambda_min = 1 - r - r * std::cos(std::numbers::pi / m);
      SlowestRate rate{rho1, n, rho, std::min(2 * r * s * s, 1 - std::abs(lambda_min)), 0, 0};
      rate.asymptotic = r * std::numbers::pi * std::numbers::pi / (2 * m * m);
      if (rate.margin > 0)
        rate.rounds_to_1e6 =
            static_cast<std::uint64_t>(std::ceil(6 * std::log(10.0) / -std::log1p(-rate.margin)));
      out.slowest = rate;
    }

    // The printed matrix: symmetric only where ρ1/2 = 1 − ρ1 (ρ1 = 2/3).
    if (n < 2)
      continue;
    Lemma68Tally& symmetric = out.claims[printed_symmetric];
    ++symmetric.premise;
    if (rho1 / 2 != 1 - rho1)
      record_example(symmetric,
                     matrix_example(symmetric.claim.id, n, rho1,
                                    "entry (" + std::to_string(n - 1) + ", " + std::to_string(n) +
                                        ") = rho1/2 = " + mc::to_string(rho1 / 2) + " but entry (" +
                                        std::to_string(n) + ", " + std::to_string(n - 1) +
                                        ") = 1 - rho1 = " + mc::to_string(1 - rho1)));
    if (n > family.printed_max_interior && n != big)
      continue;
    ++out.printed_matrices;
    const Eigen::MatrixXd p = dense(printed_t(n, rho1));
    const double general = printed_spectral_radius(n, r);
    // Similar to a symmetric tridiagonal matrix (diagonal scaling) when ρ1 ≤ 1: the pair of
    // entries beside the last diagonal one, (ρ1/2)(1 − ρ1) ≥ 0, becomes √((ρ1/2)(1 − ρ1)) twice.
    if (rho1 <= 1) {
      Eigen::VectorXd diagonal = p.diagonal(), off = p.diagonal(1);
      off(off.size() - 1) = std::sqrt(p(n - 2, n - 1) * p(n - 1, n - 2));
      const double similar = spectral_radius(tridiagonal_eigenvalues(diagonal, off));
      out.printed_disagreement = std::max(out.printed_disagreement, std::abs(general - similar));
    }
    if (general > out.printed_radius) {
      out.printed_radius = general;
      out.printed_radius_n = n;
      out.printed_radius_rho1 = rho1;
    }
    // ‖T_printed‖₂ = √λ_max(PᵀP); above 1, its top singular vector is a witness, checked
    // exactly (a double is a rational).
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> gram(p.transpose() * p);
    const Eigen::Index top = gram.eigenvalues().size() - 1;
    const double norm = std::sqrt(std::max(0.0, gram.eigenvalues()(top)));
    if (norm > out.printed_norm) {
      out.printed_norm = norm;
      out.printed_norm_n = n;
      out.printed_norm_rho1 = rho1;
    }
    Lemma68Tally& contracts = out.claims[printed_contracts];
    ++contracts.premise;
    Vector witness(n);
    for (std::size_t i = 0; i < n; ++i)
      witness[i] = Rational(gram.eigenvectors()(static_cast<Eigen::Index>(i), top));
    const Rational before = squared_norm(witness);
    const Rational after = squared_norm(apply_printed(witness, rho1));
    if (after > before)
      record_example(
          contracts,
          matrix_example(contracts.claim.id, n, rho1,
                         "||T x||^2 / ||x||^2 = " + number((after / before).convert_to<double>()) +
                             " > 1 (exactly) for x the top singular vector; ||T_printed||_2 = " +
                             number(norm)));
  }
}

// Every multiset of `robots` points of {0, L/steps, …, L}, sorted.
std::vector<Vector> grid_starts(std::size_t robots, std::size_t steps, const Rational& length) {
  Vector points;
  for (std::size_t i = 0; i <= steps; ++i) {
    Rational point(static_cast<long long>(i), static_cast<long long>(steps));
    point *= length;
    points.push_back(point);
  }
  std::vector<Vector> out;
  std::vector<std::size_t> index(robots, 0);
  while (true) {
    Vector start;
    for (std::size_t i : index)
      start.push_back(points[i]);
    out.push_back(std::move(start));
    // The next non-decreasing sequence: raise the last index below `steps`, reset the rest.
    std::size_t k = robots;
    while (k > 0 && index[k - 1] == steps)
      --k;
    if (k == 0)
      return out;
    ++index[k - 1];
    std::fill(index.begin() + static_cast<std::ptrdiff_t>(k), index.end(), index[k - 1]);
  }
}

struct DynamicsItem {
  std::size_t robots;
  std::size_t length;
  std::size_t rho1;
};

// An error vector over one common denominator: e_i = values[i]/scale. The checks of a round
// are then integer products (no gcd per operation, which is what rationals spend their time on).
struct ScaledError {
  mc::BigInteger scale = 1;
  std::vector<mc::BigInteger> values;

  Vector rationals() const {
    Vector out;
    for (const mc::BigInteger& v : values)
      out.emplace_back(v, scale);
    return out;
  }
  mc::BigInteger squared_norm() const { // ‖e‖²·scale²
    mc::BigInteger sum = 0;
    for (const mc::BigInteger& v : values)
      sum += v * v;
    return sum;
  }
};

// p[first + i] − even[first + i] for i < count, exactly.
ScaledError scaled_error(const Vector& p, const Vector& even, std::size_t first,
                         std::size_t count) {
  ScaledError e;
  for (std::size_t i = first; i < first + count; ++i)
    for (const Rational* r : {&p[i], &even[i]}) {
      const mc::BigInteger& d = denominator(*r);
      if (e.scale % d != 0)
        e.scale *= d / boost::multiprecision::gcd(e.scale, d);
    }
  for (std::size_t i = first; i < first + count; ++i)
    e.values.push_back(numerator(p[i]) * (e.scale / denominator(p[i])) -
                       numerator(even[i]) * (e.scale / denominator(even[i])));
  return e;
}

// a < b for rationals, by cross-multiplying (boost::rational's operator< divides).
bool less(const Rational& a, const Rational& b) {
  return numerator(a) * denominator(b) < numerator(b) * denominator(a);
}

// Each start is one instance of the family's limits (`stop`); none is checked after it says no.
void check_dynamics(const Lemma68Family& family, const DynamicsItem& item, std::size_t item_index,
                    FamilyStop& stop, Partial& out) {
  const Rational& length = family.lengths[item.length];
  const Rational& rho1 = family.rho1s[item.rho1];
  // ρ1 = a/b: T e = (2(b − a)e_i + a(e_{i−1} + e_{i+1}))/(2b).
  const mc::BigInteger a = numerator(rho1), b = denominator(rho1);
  const mc::BigInteger diagonal = 2 * (b - a), two_b = 2 * b;
  const std::size_t robots = item.robots, interior = robots >= 2 ? robots - 2 : 0;
  const Vector even = mc::even_spacing(robots, 0, length);
  const double rho =
      interior == 0 ? 0
                    : spectral_radius(closed_form_eigenvalues(interior, rho1.convert_to<double>()));

  std::vector<Vector> starts = grid_starts(robots, family.grid_steps, length);
  out.grid_starts += starts.size();
  SplitMix64 random(family.seed + 0x9E3779B97F4A7C15ULL * (item_index + 1));
  for (std::size_t s = 0; s < family.random_starts; ++s) {
    const auto denominator = static_cast<long long>(
        1 + random.below(static_cast<std::uint64_t>(family.random_denominator)));
    Vector start;
    for (std::size_t i = 0; i < robots; ++i) {
      Rational point(
          static_cast<long long>(random.below(static_cast<std::uint64_t>(denominator) + 1)),
          denominator);
      point *= length;
      start.push_back(point);
    }
    std::sort(start.begin(), start.end(), less);
    starts.push_back(std::move(start));
  }

  for (const Vector& start : starts) {
    if (!stop.next())
      return;
    ++out.starts;
    Vector p = start;
    ScaledError e, e_next;
    mc::BigInteger norm, norm_next; // ‖e‖²·scale², kept from the round before
    for (std::size_t k = 0; k < family.rounds; ++k) {
      const Vector next = family.step(p, 0, length, rho1);
      if (next.size() != robots)
        throw std::logic_error("lemma 6.8: the step changed the number of robots");
      ++out.rounds;
      // Counts a failure; builds the counterexample (and its text) only if it is kept.
      auto fail = [&](ClaimId id, auto why) {
        Lemma68Tally& tally = out.claims[id];
        ++tally.violations;
        tally.keep_smallest(robots, [&] {
          Lemma68Counterexample example;
          example.claim = tally.claim.id;
          example.robots = robots;
          example.rho1 = rho1;
          example.length = length;
          example.start = start;
          example.round = k;
          example.before = p;
          example.after = next;
          example.why = why();
          return example;
        });
      };
      ++out.claims[order].premise;
      for (std::size_t i = 0; i + 1 < robots; ++i)
        if (less(next[i + 1], next[i])) {
          fail(order, [&] {
            return "robot " + std::to_string(i) + " at " + mc::to_string(next[i]) +
                   " passes robot " + std::to_string(i + 1) + " at " + mc::to_string(next[i + 1]);
          });
          break;
        }
      ++out.claims[ends].premise;
      if (next.front() != 0 || (robots >= 2 && next.back() != length))
        fail(ends, [&] {
          return "the ends are at " + mc::to_string(next.front()) + " and " +
                 mc::to_string(next.back()) + ", not 0 and " + mc::to_string(length);
        });
      if (k == 0) {
        const ScaledError before = scaled_error(p, even, 0, robots),
                          after = scaled_error(next, even, 0, robots);
        if (after.squared_norm() * before.scale * before.scale >
            before.squared_norm() * after.scale * after.scale)
          ++out.first_round_growth;
      }
      if (interior >= 1) {
        e_next = scaled_error(next, even, 1, interior);
        norm_next = e_next.squared_norm();
      }
      if (k >= 1 && interior >= 1) {
        ++out.model_rounds;
        // e'_i = E'_i/Q' against (2(b − a)E_i + a(E_{i−1} + E_{i+1}))/(2bQ).
        auto model = [&](std::size_t i) {
          mc::BigInteger sum = diagonal * e.values[i];
          if (i > 0)
            sum += a * e.values[i - 1];
          if (i + 1 < interior)
            sum += a * e.values[i + 1];
          return sum;
        };
        const mc::BigInteger left_scale = two_b * e.scale;
        ++out.claims[linear_model].premise;
        for (std::size_t i = 0; i < interior; ++i)
          if (e_next.values[i] * left_scale != model(i) * e_next.scale) {
            fail(linear_model, [&] {
              return "e(k+1) = " + vector_text(e_next.rationals()) +
                     " but T e(k) = " + vector_text(apply_intended(e.rationals(), rho1)) +
                     " for e(k) = " + vector_text(e.rationals());
            });
            break;
          }
        // The printed T differs from the intended one in its last row only:
        // (1 − ρ1)e_{n−1} + ρ1/2·e_n = (2(b − a)E_{n−1} + aE_n)/(2bQ).
        ++out.claims[printed_dynamics].premise;
        if (interior >= 2 &&
            e_next.values[interior - 1] * left_scale !=
                (diagonal * e.values[interior - 2] + a * e.values[interior - 1]) * e_next.scale)
          fail(printed_dynamics, [&] {
            return "e(k+1) = " + vector_text(e_next.rationals()) +
                   " but T_printed e(k) = " + vector_text(apply_printed(e.rationals(), rho1)) +
                   " for e(k) = " + vector_text(e.rationals());
          });
        if (norm != 0) {
          // ‖e'‖² < ‖e‖² ⟺ N'·Q² < N·Q'².
          ++out.claims[contraction].premise;
          const mc::BigInteger after = norm_next * e.scale * e.scale,
                               before = norm * e_next.scale * e_next.scale;
          if (!(after < before))
            fail(contraction, [&] {
              return "||e(k+1)||^2 = " +
                     mc::to_string(Rational(norm_next, e_next.scale * e_next.scale)) +
                     " is not < ||e(k)||^2 = " + mc::to_string(Rational(norm, e.scale * e.scale));
            });
          const double ratio = std::sqrt(after.convert_to<double>() / before.convert_to<double>());
          out.ratio = std::max(out.ratio, ratio);
          out.ratio_over_rho = std::max(out.ratio_over_rho, ratio / rho);
          ++out.claims[contraction_ratio].premise;
          if (!(ratio <= rho * (1 + 1e-12)))
            fail(contraction_ratio, [&] {
              return "||e(k+1)|| / ||e(k)|| = " + number(ratio, "%.15g") +
                     " > rho(T) = " + number(rho, "%.15g");
            });
        }
      }
      p = next;
      std::swap(e, e_next);
      std::swap(norm, norm_next);
    }
    const ScaledError final_error = scaled_error(p, even, 0, robots);
    double worst = 0;
    const double scale = final_error.scale.convert_to<double>() * length.convert_to<double>();
    for (const mc::BigInteger& v : final_error.values)
      worst = std::max(worst, std::abs(v.convert_to<double>()) / scale);
    out.final_error = std::max(out.final_error, worst);
    if (final_error.squared_norm() == 0)
      ++out.reached_even;
  }
}

void merge(Partial& into, Partial&& part) {
  for (std::size_t c = 0; c < claim_count; ++c)
    into.claims[c].merge(std::move(part.claims[c]));
}

} // namespace

// ---- Public pieces

Lemma68Family::Lemma68Family() : step(mc::spacing_step) {}

std::string Lemma68Family::describe() const {
  std::vector<std::string> rhos, ls;
  for (const Rational& r : rho1s)
    rhos.push_back(mc::to_string(r));
  for (const Rational& l : lengths)
    ls.push_back(mc::to_string(l));
  return "T n x n for n = 1.." + std::to_string(max_interior) + " (printed T in full for n = 2.." +
         std::to_string(printed_max_interior) + " and " + std::to_string(max_interior) +
         "); rho1 in {" + join(rhos) + "}; dynamics: 1.." + std::to_string(max_robots) +
         " robots on [0, L], L in {" + join(ls) + "}, every multiset of {0, L/" +
         std::to_string(grid_steps) + ", ..., L} and " + std::to_string(random_starts) +
         " seeded random starts (denominators <= " + std::to_string(random_denominator) +
         ", seed " + std::to_string(seed) + ") per (robots, L, rho1), " + std::to_string(rounds) +
         " rounds each";
}

std::vector<std::string> Lemma68Counterexample::lines() const {
  std::vector<std::string> out;
  if (!length) {
    out.push_back(claim + ": n = " + std::to_string(robots - 2) +
                  " interior robots, rho1 = " + mc::to_string(rho1) + ": " + why);
    return out;
  }
  out.push_back(claim + ": " + std::to_string(robots) + " robots on [0, " + mc::to_string(*length) +
                "], rho1 = " + mc::to_string(rho1) + ", start " + vector_text(start));
  out.push_back("  round " + std::to_string(round) + " -> " + std::to_string(round + 1) + ": " +
                vector_text(before) + " -> " + vector_text(after));
  out.push_back("  " + why);
  return out;
}

std::string Lemma68Counterexample::json() const {
  auto rationals = [](const std::vector<mc::Rational>& values) {
    Json out = Json::array();
    for (const auto& v : values)
      out.push_back(mc::to_string(v));
    return out;
  };
  Json out;
  out["role"] = "counterexample";
  out["kind"] = length ? "round-of-spacing" : "matrix";
  out["claim"] = claim;
  out["robots"] = robots;
  out["rho1"] = mc::to_string(rho1);
  if (length) {
    out["length"] = mc::to_string(*length);
    out["start"] = rationals(start);
    out["round"] = round;
    out["before"] = rationals(before);
    out["after"] = rationals(after);
  }
  out["why"] = why;
  return out.dump();
}

template <> std::string Tally<Lemma68Counterexample>::summary() const {
  if (violations == 0)
    return "holds (checked " + std::to_string(premise) + " times)";
  std::string out = "violated in " + std::to_string(violations) + " of " + std::to_string(premise);
  if (smallest)
    out += "; smallest counterexample " +
           (smallest->length ? std::to_string(smallest->robots) + " robots"
                             : "n = " + std::to_string(smallest->robots - 2)) +
           ", rho1 = " + mc::to_string(smallest->rho1);
  return out;
}

std::vector<std::vector<Rational>> intended_t(std::size_t n, const Rational& rho1) {
  std::vector<std::vector<Rational>> t(n, Vector(n, Rational(0)));
  for (std::size_t i = 0; i < n; ++i) {
    t[i][i] = 1 - rho1;
    if (i > 0)
      t[i][i - 1] = rho1 / 2;
    if (i + 1 < n)
      t[i][i + 1] = rho1 / 2;
  }
  return t;
}

std::vector<std::vector<Rational>> printed_t(std::size_t n, const Rational& rho1) {
  std::vector<std::vector<Rational>> t = intended_t(n, rho1);
  if (n >= 2) {
    t[n - 1][n - 2] = 1 - rho1;
    t[n - 1][n - 1] = rho1 / 2;
  }
  return t;
}

std::vector<double> closed_form_eigenvalues(std::size_t n, double rho1) {
  std::vector<double> out;
  for (std::size_t j = n; j >= 1; --j) // cos decreases in j: ascending order
    out.push_back(
        1 - rho1 +
        rho1 * std::cos(static_cast<double>(j) * std::numbers::pi / static_cast<double>(n + 1)));
  return out;
}

std::vector<double> eigen_eigenvalues(std::size_t n, double rho1) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense_t(n, rho1, false),
                                                              Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& values = solver.eigenvalues();
  return {values.data(), values.data() + values.size()};
}

double printed_spectral_radius(std::size_t n, double rho1) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(dense_t(n, rho1, true), false);
  return solver.eigenvalues().cwiseAbs().maxCoeff();
}

std::size_t certified_up_to(std::size_t max_n, const Rational& rho1) {
  // I − T: ρ1 on the diagonal, −ρ1/2 beside it; I + T: 2 − ρ1 and ρ1/2. LDLᵀ of a symmetric
  // tridiagonal matrix: d_1 = a, d_k = a − b²/d_{k−1}; positive definite iff every d_k > 0.
  const Rational beside_squared = rho1 * rho1 / 4;
  Rational minus = rho1, plus = 2 - rho1;
  for (std::size_t n = 1; n <= max_n; ++n) {
    if (minus <= 0 || plus <= 0)
      return n - 1;
    minus = rho1 - beside_squared / minus;
    plus = (2 - rho1) - beside_squared / plus;
  }
  return max_n;
}

Lemma68Check check_lemma_6_8(const Lemma68Family& family, const CheckOptions& options) {
  const auto start = Clock::now();
  if (family.max_interior < 1 || family.max_robots < 1 || family.rounds < 1 ||
      family.grid_steps < 1 || family.random_denominator < 1 || !family.step)
    throw std::invalid_argument("lemma 6.8: an empty family");
  for (const Rational& r : family.rho1s)
    if (r <= 0)
      throw std::invalid_argument("lemma 6.8: rho1 must be > 0");
  for (const Rational& l : family.lengths)
    if (l <= 0)
      throw std::invalid_argument("lemma 6.8: L must be > 0");

  // Work: the matrices of each ρ1, then the starts of each (robots, L, ρ1).
  std::vector<DynamicsItem> dynamics;
  for (std::size_t robots = 1; robots <= family.max_robots; ++robots)
    for (std::size_t l = 0; l < family.lengths.size(); ++l)
      for (std::size_t r = 0; r < family.rho1s.size(); ++r)
        dynamics.push_back({robots, l, r});
  const std::size_t items = family.rho1s.size() + dynamics.size();
  std::vector<Partial> parts(items);
  std::atomic<std::size_t> next{0};
  FamilyStop stop(options.limits);
  auto work = [&] {
    for (std::size_t i = next++; i < items && stop.go_on(); i = next++) {
      if (i < family.rho1s.size())
        check_matrices(family, family.rho1s[i], parts[i]);
      else
        check_dynamics(family, dynamics[i - family.rho1s.size()], i, stop, parts[i]);
    }
  };
  run_on_threads(options.threads, work);

  Partial total;
  Lemma68Check check;
  for (Partial& part : parts) {
    if (part.largest_radius > total.largest_radius) {
      total.largest_radius = part.largest_radius;
      total.largest_n = part.largest_n;
      total.largest_rho1 = part.largest_rho1;
    }
    if (part.printed_radius > total.printed_radius) {
      total.printed_radius = part.printed_radius;
      total.printed_radius_n = part.printed_radius_n;
      total.printed_radius_rho1 = part.printed_radius_rho1;
    }
    if (part.printed_norm > total.printed_norm) {
      total.printed_norm = part.printed_norm;
      total.printed_norm_n = part.printed_norm_n;
      total.printed_norm_rho1 = part.printed_norm_rho1;
    }
    total.largest_disagreement = std::max(total.largest_disagreement, part.largest_disagreement);
    total.printed_disagreement = std::max(total.printed_disagreement, part.printed_disagreement);
    total.matrices += part.matrices;
    total.printed_matrices += part.printed_matrices;
    total.starts += part.starts;
    total.grid_starts += part.grid_starts;
    total.rounds += part.rounds;
    total.model_rounds += part.model_rounds;
    total.first_round_growth += part.first_round_growth;
    total.reached_even += part.reached_even;
    total.final_error = std::max(total.final_error, part.final_error);
    total.ratio = std::max(total.ratio, part.ratio);
    total.ratio_over_rho = std::max(total.ratio_over_rho, part.ratio_over_rho);
    if (part.slowest)
      check.slowest.push_back(*part.slowest);
    merge(total, std::move(part));
  }

  check.claims = std::move(total.claims);
  check.matrices = total.matrices;
  check.largest_spectral_radius = total.largest_radius;
  check.largest_at_n = total.largest_n;
  check.largest_at_rho1 = total.largest_rho1;
  check.largest_disagreement = total.largest_disagreement;
  check.printed_matrices = total.printed_matrices;
  check.printed_largest_spectral_radius = std::max(0.0, total.printed_radius);
  check.printed_largest_at_n = total.printed_radius_n;
  check.printed_largest_at_rho1 = total.printed_radius_rho1;
  check.printed_largest_disagreement = total.printed_disagreement;
  check.printed_largest_norm = std::max(0.0, total.printed_norm);
  check.printed_norm_at_n = total.printed_norm_n;
  check.printed_norm_at_rho1 = total.printed_norm_rho1;
  check.settings = family.lengths.size() * family.rho1s.size();
  check.starts = total.starts;
  check.grid_starts = total.grid_starts;
  check.rounds = total.rounds;
  check.model_rounds = total.model_rounds;
  check.first_round_growth = total.first_round_growth;
  check.reached_even = total.reached_even;
  check.largest_final_error = total.final_error;
  check.largest_ratio = total.ratio;
  check.largest_ratio_over_rho = total.ratio_over_rho;
  const ClaimVerdicts verdicts = check.sort_claims();
  const auto& violated = verdicts.violated;
  const auto& reported = verdicts.reported;

  checker::PropertyResult& r = check.result;
  r.name = "lemma-6.8";
  r.kind = "round-lemma";
  r.description = "Lemma 6.8 of seed 000 (conference Lemma 7 of seed 002): even spacing on the "
                  "curve in the limit; the matrix T of the proof and calctarget's dynamics "
                  "(exact rationals) against e(k+1) = T e(k)";
  r.states = check.starts;
  r.edges = check.rounds;
  r.depth = static_cast<std::uint32_t>(family.rounds);
  r.threads = std::max(1u, options.threads);
  r.time_unit = "rounds";
  const std::string scope = std::to_string(check.matrices) + " (n, rho1) pairs, " +
                            std::to_string(check.starts) + " starts, " +
                            std::to_string(check.rounds) + " rounds";
  if (!violated.empty()) {
    r.verdict = checker::Verdict::violated;
    r.message = "violated: " + join(violated) +
                " (smallest counterexample: " + std::to_string(check.counterexample->robots) +
                " robots, rho1 = " + mc::to_string(check.counterexample->rho1) + ", claim " +
                check.counterexample->claim + "); " + scope;
    r.trace_role = "counterexample";
    r.trace_kind = "round";
  } else {
    r.verdict = checker::Verdict::holds;
    r.message = "holds: every claim that decides the verdict, over the whole family; " + scope;
  }
  // The verdict rests on rho(T) < 1, decided exactly for every (n, rho1) of the family (a
  // proof for each); the dynamics from the grid and random starts are compared beside it.
  r.coverage = {checker::Starts::all, check.matrices, check.matrices,
                "the (n, rho1) pairs of the family", ""};
  if (!reported.empty())
    r.message += "; reported beside them, not deciding: " + join(reported) + " fails";

  r.figures.emplace_back("covered", family.describe());
  r.figures.emplace_back("matrices", std::to_string(check.matrices) +
                                         " (n, rho1) pairs; printed T in full " +
                                         std::to_string(check.printed_matrices));
  r.figures.emplace_back("start configurations", std::to_string(check.starts) + " (" +
                                                     std::to_string(check.grid_starts) +
                                                     " from the grid) over " +
                                                     std::to_string(check.settings) + " (L, rho1)");
  r.figures.emplace_back("rounds run", std::to_string(check.rounds) + " (" +
                                           std::to_string(check.model_rounds) +
                                           " checked against T)");
  r.figures.emplace_back("largest rho(T)", number(check.largest_spectral_radius, "%.12g") +
                                               " at n = " + std::to_string(check.largest_at_n) +
                                               ", rho1 = " + mc::to_string(check.largest_at_rho1));
  r.figures.emplace_back("Eigen vs closed form",
                         "largest disagreement " + number(check.largest_disagreement, "%.3g"));
  for (const SlowestRate& rate : check.slowest)
    r.figures.emplace_back(
        "rate at n = " + std::to_string(rate.n) + ", rho1 = " + mc::to_string(rate.rho1),
        "1 - rho(T) = " + number(rate.margin, "%.4g") +
            " (rho1 pi^2/2(n+1)^2 = " + number(rate.asymptotic, "%.4g") + "); " +
            (rate.rounds_to_1e6 == 0
                 ? std::string("never shrinks (rho(T) >= 1)")
                 : std::to_string(rate.rounds_to_1e6) + " rounds to shrink the error by 1e-6"));
  r.figures.emplace_back("printed T",
                         "largest rho " + number(check.printed_largest_spectral_radius, "%.12g") +
                             " at n = " + std::to_string(check.printed_largest_at_n) +
                             ", rho1 = " + mc::to_string(check.printed_largest_at_rho1) +
                             " (general solver vs its symmetrised similar form: " +
                             number(check.printed_largest_disagreement, "%.3g") +
                             "); largest ||T||_2 " + number(check.printed_largest_norm, "%.6g") +
                             " at n = " + std::to_string(check.printed_norm_at_n) +
                             ", rho1 = " + mc::to_string(check.printed_norm_at_rho1));
  r.figures.emplace_back(
      "dynamics", "largest ||e(k+1)||/||e(k)|| " + number(check.largest_ratio, "%.9g") +
                      " (ratio / rho(T) at most " + number(check.largest_ratio_over_rho, "%.9g") +
                      "); after " + std::to_string(family.rounds) + " rounds max |e_i|/L " +
                      number(check.largest_final_error, "%.3g") + ", " +
                      std::to_string(check.reached_even) +
                      " starts exactly even; ||e|| grew in "
                      "round 0 -> 1 (ends not yet set) from " +
                      std::to_string(check.first_round_growth) + " starts");
  check.figure_claims("reported ");
  check.note_statements("reported ");
  check.note_witnesses();
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  stop.mark(check.result, check.starts); // (the starts are its instances)
  return check;
}

} // namespace proofs
