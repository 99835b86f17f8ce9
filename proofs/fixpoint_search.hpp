#pragma once
// A seeded random search for the lemmas about runs to the fixed point (6.5, 6.6, 6.7 and
// every FixpointLemma, proofs/fixpoint_lemma.hpp), beside their exhaustive check over a small
// Family: random populations of hundreds of robots per region on grids up to 4×4, each run
// to its fixed point with RoundSystem::run_to_fixpoint (the default order) and measured
// with the lemma's `evaluate`. A violated claim is shrunk (a smaller grid, fewer robots,
// smaller counts, smaller k and q) to a small counterexample.
//
// As for the one-step lemmas (search_random, proofs/round_lemma.hpp), the verdict is never
// a plain "holds": a sample is a bounded part of an unbounded space. Without a violation
// the verdict is *incomplete* with the message "holds on N samples (a random search, not
// a proof)"; with one it is *violated*, with the shrunk counterexample in the notes.
//
// Reproducible: the samples are drawn in order from one SplitMix64 of the seed before any
// is run, the runs are split between threads and merged in sample order, and the shrinker
// is deterministic: the same seed gives the same figures for every thread count.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "proofs/fixpoint_lemma.hpp"

namespace proofs {

struct FixpointSearchOptions {
  std::uint64_t seed = 1;
  std::uint64_t samples = 200;
  mc::Neighbourhood neighbourhood = mc::Neighbourhood::four;
  int min_side = 2;
  int max_side = 4;
  // A region holds 0..max_count robots. A third of the samples each: every region uniform
  // in 0..max_count; piles (1 to 3 regions with 1..max_count, the rest empty); a plateau
  // (a level B, each region B ± B/4, an eighth of the regions a dip to 0..B/2).
  RobotCount max_count = 500;
  std::vector<std::string> curves = curve_names(); // named curves (proofs/family.hpp)
  // A third of the samples on a random grid path (proofs/random_curve.hpp) instead; false:
  // named curves only. given_curve: every sample on that curve, m its side.
  bool grid_paths = true;
  std::optional<GivenCurve> given_curve;
  std::vector<RobotCount> ks{1, 2, 3};
  std::vector<mc::Rational> rho2s{{1, 2}, {9, 10}, {1, 10}, {2, 3}};
  mc::Rational rho1{1, 2};          // not used by assign; fixed
  std::size_t max_rounds = 100'000; // a run without a fixed point by then is reported
  bool shrink = true;
  unsigned threads = 1;                    // the runs are split between threads; the same figures
  const checker::Limits* limits = nullptr; // the property's limits (family_stop.hpp)
};

// One sample: a setting and the counts M_0.
struct FixpointSample {
  Setting setting;
  Counts start;
};

// The samples of a search, in order (what search_fixpoint runs). Throws
// std::invalid_argument on min_side < 1, max_side < min_side, max_count < 0, an empty list
// of curves, k or ρ2, an unknown curve or no sample.
// With `stop`: drawing ends early when it says so (the samples drawn so far are returned),
// so that the limits hold while a large search is drawn.
std::vector<FixpointSample> fixpoint_samples(const FixpointSearchOptions& options,
                                             FamilyStop* stop = nullptr);

// The search: every sample run to its fixed point and measured; the smallest violation of
// each claim (fewest robots, then the smaller grid, then the first sample) shrunk. The
// FixpointCheck's `instances` are the samples run, `rounds` the rounds run, `skipped` 0.
FixpointCheck search_fixpoint(const FixpointLemma& lemma, const FixpointSearchOptions& options);

// The measurement of claims[claim] on the run of `sample` to its fixed point when it
// exceeds its bound, as a witness; nullopt when it holds there, its premise is not met or
// there is no fixed point within max_rounds.
std::optional<BoundWitness> fixpoint_violation(const FixpointLemma& lemma, std::size_t claim,
                                               const FixpointSample& sample,
                                               std::size_t max_rounds = 100'000);

// Shrinks a violation of claims[claim] while it stays one, with the one-step lemmas'
// shrinker (proofs/round_lemma.hpp, shrink_instance). Deterministic. The curve of a shrunk
// grid or q is named "shrunk from <curve>".
BoundWitness shrink_fixpoint(const FixpointLemma& lemma, std::size_t claim,
                             const BoundWitness& start, std::size_t max_rounds = 100'000);

} // namespace proofs
