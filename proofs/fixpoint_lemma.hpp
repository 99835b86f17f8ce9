#pragma once
// What the lemmas about runs to the fixed point (6.2, 6.3, 6.5, 6.6, 6.7) share: a lemma is a
// list of claims, each a figure measured on one run and the paper's bound for that instance;
// the check runs every configuration of a Family to its fixed point and keeps, per claim, the
// largest measured value, the instance closest to its bound (largest value/bound) and the
// smallest counterexample (fewest robots, then the smaller grid, then the first in
// enumeration order). The seeded random search over larger instances is
// proofs/fixpoint_search.hpp.
//
// Units, as the lemmas take them: ρ3 = q_max²/((1 − ρ2)σ) (seed 000 line 1015) is a length,
// not a number; it is taken with σ as the unit of length, so ρ3 = n_max²/(1 − ρ2) with
// q_max = n_max·σ (and ρ3 = 0 without a curve, where the paper's "ρ3 > 1" fails). n is the
// number of robots, t0 = 0, and every bound is an exact rational.
//
// Runs use the default order of run_to_fixpoint (every VN's lower set by increasing region
// id); the lemmas claim every run.
//
// Symmetry. The default order (lower by increasing id) is not invariant under the
// rotations and reflections of the square, so the run from σ(M) is the σ-image of the run
// from M under another order of lower, not the default one. With use_symmetry (the
// default) one configuration per orbit is run, in the default order: the family is covered
// once per orbit, in one order. use_symmetry = false runs every configuration.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "checker/result.hpp"
#include "models/mc/round.hpp"
#include "proofs/claim_tally.hpp"
#include "proofs/family.hpp"
#include "proofs/round_lemma.hpp"

namespace proofs {

// One run of the default order from a configuration to its fixed point (with history).
struct FixpointInstance {
  const Setting& setting;
  const mc::RoundSystem& system;
  const Counts& start;        // M_0
  const mc::FixpointRun& run; // M_0 .. M_F, T_out, T_stab
  mc::Rational rho3;          // q_max²/((1 − ρ2)σ), σ the unit of length
};

// A figure measured on one run against the paper's bound for the instance.
struct Measurement {
  mc::Rational value;
  mc::Rational bound;
  std::string detail; // where it is realised (regions, rounds), one line
};

// id ("6.5", "L5", "6.7 step"), statement ("T_out <= ..."), source ("seed 000 lines ...; seed
// 002 line ..."), decides_verdict (false: a step of the paper's proof, reported only).
using BoundClaim = ClaimStatement;

struct FixpointLemma {
  std::string name;        // "lemma-6.5"
  std::string description; // one line
  std::vector<BoundClaim> claims;
  // Sets out[i] for claims[i] (reset to nullopt by the caller); nullopt: premise not met.
  std::function<void(const FixpointInstance&, std::vector<std::optional<Measurement>>& out)>
      evaluate;
};

// One instance with its measured figure, printable round by round.
struct BoundWitness {
  std::string claim;
  Setting setting;
  Counts start;
  Measurement measurement;
  std::size_t t_out = 0, t_stab = 0, fixpoint_round = 0;

  RobotCount robots() const { return mc::total(start); }
  // Fewest robots, then the smaller grid.
  std::tuple<RobotCount, int> order_key() const { return {robots(), setting.m}; }
  bool violated() const { return measurement.value > measurement.bound; }
  // The instance, q, every M_t to the fixed point (up to 40 rounds), T_out, T_stab, and the
  // measured figure beside its bound.
  std::vector<std::string> lines() const;
  // The same as a JSON object (proofs/witness_json.hpp), as text; every round to the fixed
  // point.
  std::string json() const;
};

// A claim that is a bound over a check: `premise` the instances on which the figure was
// measured, `violations` those where value > bound; `largest`, `tightest` (the largest
// value/bound, bound > 0 or violated) and `smallest` (the smallest counterexample).
// verdict(): violated when violations > 0, else holds.
using BoundTally = Tally<BoundWitness>;
// "holds on 123 instances; largest measured 7 (its bound …) at …"
template <> std::string Tally<BoundWitness>::summary() const;

// Is measurement a closer to its bound than b (a larger value/bound, exactly), as the two
// checks keep `tightest`? They differ when violations compete:
//   - the exhaustive check (check_fixpoint_family): a violation of a bound <= 0 is closest
//     (the first of them stays), then the larger value/bound, violations of a positive bound
//     included;
//   - the random search (search_fixpoint): any violation is closest (the first stays), then
//     the larger value/bound.
bool closer_to_bound(const Measurement& a, const Measurement& b);
bool closer_to_bound_first_violation(const Measurement& a, const Measurement& b);

struct FixpointCheck : Check<BoundWitness> {
  std::uint64_t instances = 0; // runs to the fixed point
  std::uint64_t skipped = 0;   // symmetric duplicates not run
  std::uint64_t rounds = 0;    // rounds run, over all instances
  // `counterexample`: the smallest over the claims deciding the verdict.
};

// The default family of the fixed-point lemmas for one neighbourhood: 1×1 with counts 0..20,
// 2×2 with counts 0..8
// and 3×3 with counts 0..2, every named curve, k ∈ {1, 2, 3}, ρ2 ∈ {1/2, 9/10, 1/10, 2/3}.
Family fixpoint_family(mc::Neighbourhood neighbourhood);

// ρ3 = q_max²/((1 − ρ2)σ) with σ = 1 (q in units of σ); 0 without a curve.
mc::Rational rho3(const mc::RoundSystem& system);

// Runs every configuration of the family (one per orbit with use_symmetry) to its fixed
// point in the default order and measures every claim. Settings are split between
// `options.threads` threads and merged in order: the same figures for every thread count.
FixpointCheck check_fixpoint_family(const FixpointLemma& lemma, const Family& family,
                                    const CheckOptions& options = {});

// Sets check.counterexample (the smallest over the claims that decide the verdict) and the
// head of check.result (name, kind, description, instances as states, rounds as edges,
// seconds, threads); returns the claims by verdict (violated: those deciding the verdict;
// reported: the proof steps that fail).
ClaimVerdicts start_result(FixpointCheck& check, const FixpointLemma& lemma, double seconds,
                           unsigned threads);

// Adds to check.result what every fixed-point check reports: per claim its summary (a
// figure), its statement with its source and its smallest counterexample or largest value
// round by round (notes), and the trace role when there is a counterexample.
void report_claims(FixpointCheck& check);

} // namespace proofs
