// Lemma 6.8 / conference Lemma 7 (proofs/lemma_6_8.hpp): the matrix T of the proof against its
// closed-form spectrum, one hand-computed run of calctarget against e(k+1) = T e(k), the
// printed matrix's typo, the default check's figures, and failing variants (ρ1 > 1, a
// Gauss–Seidel step).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "models/mc/spacing.hpp"
#include "proofs/lemma_6_8.hpp"

using namespace proofs;
using mc::Rational;

namespace {

std::vector<Rational> times(const std::vector<std::vector<Rational>>& t,
                            const std::vector<Rational>& x) {
  std::vector<Rational> y(x.size(), Rational(0));
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      y[i] += t[i][j] * x[j];
  return y;
}

// A small family: quick, and every claim still exercised.
Lemma68Family small() {
  Lemma68Family family;
  family.max_interior = 12;
  family.printed_max_interior = 6;
  family.rho1s = {Rational(1, 10), Rational(2, 3), Rational(1)};
  family.max_robots = 5;
  family.lengths = {Rational(7, 3)};
  family.random_starts = 3;
  family.rounds = 6;
  return family;
}

} // namespace

TEST_CASE("lemma 6.8: Eigen's eigenvalues of T are the closed form's", "[proofs][lemma-6.8]") {
  for (auto [n, rho1] :
       {std::pair<std::size_t, double>{1, 0.5}, {2, 0.1}, {7, 0.9}, {50, 0.99}, {120, 1.0}}) {
    INFO("n = " << n << ", rho1 = " << rho1);
    const std::vector<double> eigen = eigen_eigenvalues(n, rho1);
    const std::vector<double> closed = closed_form_eigenvalues(n, rho1);
    REQUIRE(eigen.size() == n);
    for (std::size_t j = 0; j < n; ++j)
      CHECK(std::abs(eigen[j] - closed[j]) < 1e-12);
    // ρ(T) = λ_max = 1 − ρ1(1 − cos(π/(n+1))) for ρ1 ≤ 1.
    CHECK(closed.back() ==
          Approx(1 - rho1 * (1 - std::cos(M_PI / static_cast<double>(n + 1)))).epsilon(1e-14));
  }
  // At ρ1 = 1 the smallest eigenvalue is −cos(π/(n+1)): close to −1, and |λ_min| = λ_max.
  const std::vector<double> limit = closed_form_eigenvalues(200, 1.0);
  CHECK(limit.front() == Approx(-limit.back()).epsilon(1e-12));
  CHECK(limit.front() > -1);
}

TEST_CASE("lemma 6.8: rho(T) < 1 certified exactly by LDL^T pivots", "[proofs][lemma-6.8]") {
  CHECK(certified_up_to(200, Rational(1, 10)) == 200);
  CHECK(certified_up_to(200, Rational(1)) == 200);
  // ρ1 = 3/2: λ_min = 1 − 3/2·(1 + cos(π/3)) = −5/4 at n = 2.
  CHECK(certified_up_to(200, Rational(3, 2)) == 1);
  // ρ1 = 2: I + T has 0 on its diagonal.
  CHECK(certified_up_to(200, Rational(2)) == 0);
}

TEST_CASE("lemma 6.8: two rounds of calctarget by hand, and e(k+1) = T e(k)",
          "[proofs][lemma-6.8]") {
  // 4 robots on [0, 1], ρ1 = 1/2; the ends are set, the interior follows line 38.
  const Rational half(1, 2);
  const std::vector<Rational> start{0, Rational(1, 4), half, 1};
  const std::vector<Rational> first = mc::spacing_step(start, 0, 1, half);
  // 1/2 + 1/2·((1/4 + 1)/2 − 1/2) = 9/16.
  CHECK(first == std::vector<Rational>{0, Rational(1, 4), Rational(9, 16), 1});
  const std::vector<Rational> second = mc::spacing_step(first, 0, 1, half);
  CHECK(second == std::vector<Rational>{0, Rational(17, 64), Rational(19, 32), 1});
  // Even spacing 0, 1/3, 2/3, 1: e(1) = (−1/12, −5/48), e(2) = (−13/192, −7/96).
  const std::vector<Rational> e1{Rational(1, 4) - Rational(1, 3), Rational(9, 16) - Rational(2, 3)};
  const std::vector<Rational> e2{Rational(17, 64) - Rational(1, 3),
                                 Rational(19, 32) - Rational(2, 3)};
  CHECK(e2 == std::vector<Rational>{Rational(-13, 192), Rational(-7, 96)});
  CHECK(times(intended_t(2, half), e1) == e2);
  // The printed last row (1 − ρ1, ρ1/2) gives −13/192 for e_2, not −7/96.
  CHECK(times(printed_t(2, half), e1)[1] == Rational(-13, 192));
}

TEST_CASE("lemma 6.8: the printed T is not symmetric (except at rho1 = 2/3)",
          "[proofs][lemma-6.8]") {
  const auto printed = printed_t(3, Rational(1, 10));
  CHECK(printed[1][2] == Rational(1, 20));
  CHECK(printed[2][1] == Rational(9, 10));
  CHECK(printed[2][2] == Rational(1, 20));
  const auto intended = intended_t(3, Rational(1, 10));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      CHECK(intended[i][j] == intended[j][i]);
  // ρ1/2 = 1 − ρ1 at ρ1 = 2/3: there the printed matrix is the intended one.
  CHECK(printed_t(4, Rational(2, 3)) == intended_t(4, Rational(2, 3)));
  // Its spectral radius is < 1 (a nonnegative matrix with row sums <= 1), though its norm is not.
  CHECK(printed_spectral_radius(2, 0.1) == Approx(0.95).epsilon(1e-12)); // rank 1: 9/10 + 1/20
}

TEST_CASE("lemma 6.8: the default check holds, with its coverage", "[proofs][lemma-6.8]") {
  const Lemma68Check check = check_lemma_6_8({}, {.threads = 2});
  const checker::PropertyResult& r = check.result;
  CHECK(r.name == "lemma-6.8");
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(check.matrices == 1400); // n = 1..200, 7 values of ρ1
  CHECK(check.printed_matrices == 224);
  CHECK(check.settings == 14);
  CHECK(check.starts == 20'244);
  CHECK(check.grid_starts == 18'004); // 2 · 7 · Σ_{r=1..8} C(r + 4, 4)
  CHECK(check.rounds == 242'928);
  CHECK(check.model_rounds == 213'444);
  CHECK(r.states == check.starts);
  CHECK(r.edges == check.rounds);
  CHECK(check.claim("T: rho < 1").premise == 1400);
  CHECK(check.claim("linear model").premise == 213'444);
  CHECK(check.claim("contraction").premise == 211'313);
  for (const char* id : {"T: rho < 1", "order", "ends", "linear model", "contraction",
                         "T: Eigen = closed form", "contraction ratio (doubles)"})
    CHECK(check.claim(id).violations == 0);
  CHECK(check.largest_at_n == 200);
  CHECK(check.largest_at_rho1 == Rational(1, 10));
  CHECK(check.largest_spectral_radius == Approx(1 - 0.2 * std::pow(std::sin(M_PI / 402), 2)));
  CHECK(check.largest_disagreement < 1e-13);
  CHECK(check.first_round_growth == 0);
  // The printed matrix: asymmetric for every n >= 2 but at ρ1 = 2/3; not the dynamics; and not
  // a contraction in ||.||_2 (from n = 2 at ρ1 = 1/10).
  const Lemma68Tally& symmetric = check.claim("printed T: symmetric");
  CHECK(symmetric.violations == 1194);
  REQUIRE(symmetric.smallest);
  CHECK(symmetric.smallest->robots == 4);
  CHECK(check.claim("printed T: the dynamics").violations == 174'843);
  const Lemma68Tally& contracts = check.claim("printed T: contracts");
  CHECK(contracts.violations == 64);
  REQUIRE(contracts.smallest);
  CHECK(contracts.smallest->robots == 4);
  CHECK(contracts.smallest->rho1 == Rational(1, 10));
  CHECK(check.printed_largest_spectral_radius < 1);
  CHECK(check.printed_largest_norm > 1.27);
}

TEST_CASE("lemma 6.8: the same figures on one thread and two", "[proofs][lemma-6.8]") {
  const Lemma68Check one = check_lemma_6_8(small(), {.threads = 1});
  const Lemma68Check two = check_lemma_6_8(small(), {.threads = 2});
  CHECK(one.result.verdict == checker::Verdict::holds);
  CHECK(one.result.figures == two.result.figures);
  CHECK(one.result.notes == two.result.notes);
}

TEST_CASE("lemma 6.8: rho1 = 3/2 breaks the matrix claim and the dynamics", "[proofs][lemma-6.8]") {
  Lemma68Family family = small();
  family.rho1s = {Rational(3, 2)};
  const Lemma68Check check = check_lemma_6_8(family);
  CHECK(check.result.verdict == checker::Verdict::violated);
  const Lemma68Tally& radius = check.claim("T: rho < 1");
  CHECK(radius.violations == 11); // n = 2..12
  REQUIRE(radius.smallest);
  CHECK(radius.smallest->robots == 4);
  CHECK(check.claim("order").violations > 0);
  CHECK(check.claim("contraction").violations > 0);
  CHECK(check.claim("linear model").violations == 0); // the model is still the dynamics
  REQUIRE(check.counterexample);
  CHECK(check.counterexample->robots == 4);
}

TEST_CASE("lemma 6.8: a Gauss-Seidel step is caught by the linear model", "[proofs][lemma-6.8]") {
  // Updating in place (each robot sees its left neighbour's new parameter) is not Fig. 7,
  // where seq is computed once (line 26) before any target changes.
  Lemma68Family family = small();
  family.step = [](const std::vector<Rational>& sorted, const Rational& inf, const Rational& sup,
                   const Rational& rho1) {
    std::vector<Rational> p = sorted;
    for (std::size_t k = 0; k < p.size(); ++k)
      if (k == 0)
        p[k] = inf;
      else if (k + 1 == p.size())
        p[k] = sup;
      else
        p[k] = p[k] + rho1 * ((p[k - 1] + p[k + 1]) / 2 - p[k]);
    return p;
  };
  const Lemma68Check check = check_lemma_6_8(family);
  CHECK(check.result.verdict == checker::Verdict::violated);
  const Lemma68Tally& model = check.claim("linear model");
  REQUIRE(model.smallest);
  CHECK(model.smallest->robots == 4); // with 3 robots both orders agree from round 1 on
  CHECK(check.claim("ends").violations == 0);
  CHECK_FALSE(check.result.notes.empty());
}
