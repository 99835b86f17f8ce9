#pragma once
// Lemma 6.8 of seed 000 (journal) = Lemma 7 of seed 002 (conference): after T_stab the robots
// of each region on the curve converge to even spacing. Checked in two parts: the matrix T of
// the proof (its spectral radius, for every size up to N), and the dynamics of calctarget
// (mc::spacing_step) in exact rationals against the proof's linear model e(k+1) = T·e(k).
//
// Seed 002 (conference), §VI, line 304:
//   "Lemma 7: Consider a sequence of rounds t_1 = T_stab, …, t_n. As n → ∞, the locations of
//    CNs in B_h, h ∈ In, are evenly spaced on Γ_h."
// Seed 000 (journal), §6.2, line 1129: the same ("uniformly spaced on Γ_u"), no proof.
// The proof (seed 002 lines 306–318): from round t_3 on the first and last robots sit at
// inf P_h and sup P_h (Fig. 7 lines 35–36) and the n interior ones follow line 38,
//   p_i(t_{k+1}) = p_i(t_k) + ρ1((p_{i−1}(t_k) + p_{i+1}(t_k))/2 − p_i(t_k));
// with p̄_i = p_0 + i/(n+1)·(p_{n+1} − p_0) and e_i(k) = p_i(t_k) − p̄_i (line 312):
//   e_i(k+1) = (1 − ρ1)e_i(k) + ρ1/2·(e_{i−1}(k) + e_{i+1}(k)), e_1, e_n with one neighbour,
// "e(k+1) = T e(k)" (line 314), and "Using symmetry of T, ρ1 ≤ 1, […] the largest eigenvalue
// of T is less than 1" (line 318). ρ1 ∈ (0, 1) for the algorithm (seed 000 line 858; seed 002
// line 166); ρ1 = 1 is the proof's limit.
//
// A typo: the matrix printed at line 316 ends with the row "0 … 0 0 1−ρ1 ρ1/2", which is
// neither symmetric nor the text's e_n(k+1) = (1−ρ1)e_n(k) + ρ1/2·e_{n−1}(k). The intended T
// is the symmetric tridiagonal matrix (1 − ρ1 on the diagonal, ρ1/2 beside it); the printed
// one is checked beside it and reported, never deciding the verdict.
//
// Certifying ρ(T) < 1. The eigenvalues of T are λ_j = 1 − ρ1 + ρ1·cos(jπ/(n+1)), j = 1..n
// (tridiagonal Toeplitz), so for 0 < ρ1 ≤ 1: λ_max = 1 − ρ1(1 − cos(π/(n+1))) < 1 and
// λ_min = 1 − ρ1(1 + cos(π/(n+1))) > 1 − 2ρ1 ≥ −1 (at ρ1 = 1, λ_min → −1 as n grows). The
// check decides it exactly instead: T is symmetric, so ρ(T) < 1 ⟺ I − T and I + T are
// positive definite ⟺ every pivot of their LDLᵀ factorisations is > 0, computed in
// rationals (the pivots of the n×n matrix are the first n of the N×N one). The closed form
// and Eigen's eigenvalues are compared beside it, in doubles.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "checker/result.hpp"
#include "models/mc/rational.hpp"
#include "proofs/claim_tally.hpp"
#include "proofs/round_lemma.hpp"

namespace proofs {

// calctarget lines 35–38 on one region: (sorted parameters, inf, sup, ρ1) -> parameters.
using SpacingStep =
    std::function<std::vector<mc::Rational>(const std::vector<mc::Rational>&, const mc::Rational&,
                                            const mc::Rational&, const mc::Rational&)>;

struct Lemma68Family {
  // The matrix T, n×n for n = 1..max_interior, for each ρ1.
  std::size_t max_interior = 200;
  // The printed matrix in full (Eigen's general solver, ‖·‖₂) for n = 2..printed_max_interior
  // and n = max_interior.
  std::size_t printed_max_interior = 32;
  std::vector<mc::Rational> rho1s{{1, 10}, {1, 4}, {1, 2}, {2, 3}, {9, 10}, {99, 100}, {1}};
  // The dynamics: 1..max_robots robots (the ends included) on P_h = [0, L], L in lengths.
  std::size_t max_robots = 8;
  std::vector<mc::Rational> lengths{{1}, {7, 3}};
  // Starts: for r robots, every multiset of r points of {0, L/grid_steps, …, L} ...
  std::size_t grid_steps = 4;
  // ... and, per (robots, L, ρ1), this many sorted random points p = L·a/b, b in
  // 1..random_denominator, a in 0..b (SplitMix64 from seed; the same on every platform).
  std::size_t random_starts = 20;
  std::int64_t random_denominator = 100;
  std::uint64_t seed = 1;
  std::size_t rounds = 12; // K rounds from each start
  // The dynamics under test; tests substitute a wrong one.
  SpacingStep step;

  Lemma68Family(); // step = mc::spacing_step
  std::string describe() const;
};

// A claim that fails: the matrix (n interior robots, ρ1) or one round of one start.
struct Lemma68Counterexample {
  std::string claim;
  std::size_t robots = 0; // matrix claims: n + 2 (the n interior robots and the two ends)
  mc::Rational rho1;
  std::optional<mc::Rational> length;      // dynamics only
  std::vector<mc::Rational> start;         // dynamics only
  std::size_t round = 0;                   // dynamics: round k -> k+1 (k from 0)
  std::vector<mc::Rational> before, after; // dynamics: parameters at k and k+1
  std::string why;

  // Fewest robots.
  std::size_t order_key() const { return robots; }
  std::vector<std::string> lines() const;
  // The same as a JSON object (proofs/witness_json.hpp), as text.
  std::string json() const;
};

// A claim of Lemma 6.8 over the check: `premise` how often it was checked, `violations` how
// often it failed, the smallest counterexample. A claim that does not decide the verdict is a
// typo of the printed matrix or a numerical cross-check.
using Lemma68Tally = Tally<Lemma68Counterexample>;
// "holds (checked 123 times)", "violated in 4 of 123; smallest counterexample …"
template <> std::string Tally<Lemma68Counterexample>::summary() const;

// ρ(T) for the largest n beside the rounds it takes to shrink the error by 10^-6.
struct SlowestRate {
  mc::Rational rho1;
  std::size_t n = 0;
  double spectral_radius = 0;
  double margin = 0;               // 1 − ρ(T), from the closed form (2ρ1 sin²(π/2(n+1)))
  double asymptotic = 0;           // ρ1π²/(2(n+1)²)
  std::uint64_t rounds_to_1e6 = 0; // 0: never (ρ(T) ≥ 1)
};

struct Lemma68Check : Check<Lemma68Counterexample> {
  // The matrix T.
  std::uint64_t matrices = 0;         // (n, ρ1) pairs
  double largest_spectral_radius = 0; // Eigen
  std::size_t largest_at_n = 0;       // where
  mc::Rational largest_at_rho1;
  double largest_disagreement = 0;  // max |Eigen − closed form| over every eigenvalue
  std::vector<SlowestRate> slowest; // per ρ1, at n = max_interior
  // The printed T (n ≥ 2).
  std::uint64_t printed_matrices = 0; // (n, ρ1) pairs computed in full
  double printed_largest_spectral_radius = 0;
  std::size_t printed_largest_at_n = 0;
  mc::Rational printed_largest_at_rho1;
  double printed_largest_disagreement = 0; // general solver vs its symmetrised similar form
  double printed_largest_norm = 0;         // ‖T_printed‖₂
  std::size_t printed_norm_at_n = 0;
  mc::Rational printed_norm_at_rho1;

  // The dynamics.
  std::uint64_t settings = 0;           // (L, ρ1)
  std::uint64_t starts = 0;             // start configurations, over every setting
  std::uint64_t grid_starts = 0;        // of which from the grid
  std::uint64_t rounds = 0;             // rounds run
  std::uint64_t model_rounds = 0;       // rounds checked against e(k+1) = T·e(k)
  std::uint64_t first_round_growth = 0; // starts whose ‖e‖ grew in round 0 -> 1 (ends not set)
  std::uint64_t reached_even = 0;       // starts at exactly even spacing after K rounds
  double largest_final_error = 0;       // max |e_i(K)|/L
  double largest_ratio = 0;             // max ‖e(k+1)‖/‖e(k)‖, k ≥ 1 (doubles)
  double largest_ratio_over_rho = 0;    // max of that ratio / ρ(T_n)

  // `counterexample`: the smallest over the claims deciding the verdict.
};

// The symmetric T (intended) and the printed one (line 316), n×n, exactly.
std::vector<std::vector<mc::Rational>> intended_t(std::size_t n, const mc::Rational& rho1);
std::vector<std::vector<mc::Rational>> printed_t(std::size_t n, const mc::Rational& rho1);

// λ_j = 1 − ρ1 + ρ1·cos(jπ/(n+1)), j = 1..n, ascending.
std::vector<double> closed_form_eigenvalues(std::size_t n, double rho1);

// Eigen's eigenvalues of the intended T (SelfAdjointEigenSolver), ascending.
std::vector<double> eigen_eigenvalues(std::size_t n, double rho1);

// ρ(T_printed) by Eigen's general EigenSolver.
double printed_spectral_radius(std::size_t n, double rho1);

// The largest n' ≤ max_n with ρ(T) < 1 for every n ≤ n', decided exactly by the LDLᵀ pivots
// of I − T and I + T (0: fails already at n = 1).
std::size_t certified_up_to(std::size_t max_n, const mc::Rational& rho1);

// Claims (ids): "T: rho < 1", "order", "ends", "linear model", "contraction" decide the
// verdict; "T: Eigen = closed form", "contraction ratio (doubles)", "printed T: symmetric",
// "printed T: the dynamics", "printed T: contracts" are reported beside them.
Lemma68Check check_lemma_6_8(const Lemma68Family& family = {}, const CheckOptions& options = {});

} // namespace proofs
