#pragma once
// Theorem 6.9 of seed 000 (journal) = Theorem 1 of seed 002 (conference), checked in two
// parts: at count level over the fixed-point family, and with robots' positions
// (models/mc/positions.hpp) over a family of small exact instances.
//
// Seed 000, §6.2, lines 1133–1142 (seed 002 line 234 is the same with "evenly spaced"):
//   "THEOREM 6.9. If there are no fail or restart actions for robots at or after some round
//    t0, then within a finite number of rounds after t0:
//    (1) The set of CNs assigned to each VNu, u ∈ U, becomes fixed, and the size of the set
//        is proportional to the quantized length qu, within a constant additive term
//        10(2m−1)/(qmin ρ2).
//    (2) All client nodes in a region u ∈ U for which qu ≠ 0 are located on Γu and
//        uniformly spaced on Γu in the limit."
// and (line 1121, seed 002 line 302): "by the beginning of round Tstab + 2, all CNs in Cin
// are located on the curve Γ".
//
// Count level (`counts`): Lemma 6.7's claims over a Family (every run reaches its fixed
// point — run_to_fixpoint throws otherwise — and is proportional there).
//
// Positions: every configuration of 0..c robots per region, each robot at a fixed spot
// of its region (spot j mod 4 for its j-th robot: the centre, a point near the top-left
// corner, a point of Γ_u when u meets Γ, a point near the bottom-right corner), run round
// by round under both membership readings (positions.hpp). Per run:
//   - "fixed": the assignment becomes fixed. Decided either way: a round that
//     PositionSystem::certifies_fixed proves it fixed for ever; a state (every robot's
//     position and VN) that repeats an earlier one with some robot changing VN in between
//     proves it never fixed (the round is deterministic, so the run is periodic from there).
//     Neither within max_rounds: a proof by over-approximation is tried (no count vector
//     that assign and any migrations can reach lets a round certify: never fixed; see
//     never_certifiable in the .cpp); failing that, undecided, and the verdict is at best
//     incomplete.
// The random search (samples > 0) shrinks the smallest counterexample of each claim by
// removing robots one at a time while the claim still fails.
//   - "proportional": at the fixed assignment, max |y_u/q_u − y_v/q_v| over In ≤ the bound.
//   - "on curve": at round T + 2 (T the certified round) every robot of a region on the
//     curve lies on the closure of Γ_u.
//   - "spacing": from T + 2 on, for spacing_rounds rounds, every region's squared distance
//     to even spacing, Σ(p_i − p̄_i)², decreases strictly while it is not zero — what
//     e(k+1) = T·e(k) with ρ(T) < 1 (Lemma 6.8) gives; exact rationals.
// Runs use the default order of assign and the lowest-ids reassignment.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "checker/result.hpp"
#include "models/mc/positions.hpp"
#include "proofs/fixpoint_lemma.hpp"

namespace proofs {

// A named exact curve (polyline with rational segment lengths) for an m×m grid of side 1.
struct NamedCurve {
  std::string name;
  mc::Curve curve;
};

// The curves of the positional family for side m >= 1: a horizontal line through
// the middle of row ⌊m/2⌋ drawn eastward and westward, an L, a closed square through region centres
// (m >= 2), a 3-4-5 segment crossing three regions and a stub that ends on the line x = 1, so that
// region 1 owns one point of Γ (both m = 2).
std::vector<NamedCurve> positional_curves(int m);

struct PositionalFamily {
  std::vector<int> sides{1, 2};
  std::vector<mc::Neighbourhood> neighbourhoods{mc::Neighbourhood::four, mc::Neighbourhood::eight};
  RobotCount max_count = 2; // robots per region: 0..c
  std::vector<RobotCount> ks{1, 2};
  std::vector<mc::Rational> rho1s{{1, 2}, {9, 10}};
  std::vector<mc::Rational> rho2s{{1, 2}, {9, 10}};
  std::vector<mc::Membership> memberships{mc::Membership::position, mc::Membership::assigned};
  mc::Rational sigma{1, 4};
  std::size_t max_rounds = 40;    // to decide "fixed"
  std::size_t spacing_rounds = 5; // rounds of the spacing claim after T + 2
  // samples > 0: a seeded random search instead of every configuration — each sample a
  // setting of the family and 0..sample_max_count robots per region at random points
  // (col + a/8, row + c/8); its verdict is at best incomplete, "holds on N samples".
  std::uint64_t samples = 0;
  std::uint64_t seed = 1;
  RobotCount sample_max_count = 12;
  // With samples > 0: this many random grid paths per side m >= 2 beside the named curves,
  // drawn from the seed (axis-parallel legs, so that positions are exact;
  // proofs/random_curve.hpp).
  std::size_t random_curves = 3;
  // Set: this curve instead of positional_curves(m); `sides` must be its side alone.
  std::optional<NamedCurve> given_curve;
  // Non-empty: part (2) is not checked, for this reason (a curve given as q alone has no
  // geometry); the verdict is then at best incomplete.
  std::string not_checked;

  std::string describe() const;
};

// One run with its claim's verdict, printable round by round.
struct PositionalWitness {
  std::string claim;
  std::string setting; // "m = 2, neighbourhood 4, curve westward, k = 1, rho1 = 1/2, ..."
  std::size_t robots = 0;
  int m = 0;
  std::string why;                // one line
  std::vector<std::string> lines; // the rounds of the run (up to 8)
  std::size_t setting_index = 0;  // in the family's enumeration order
  std::vector<mc::Robot> start;   // the robots at round 0

  // Fewest robots, then the smaller grid.
  std::tuple<std::size_t, int> order_key() const { return {robots, m}; }
  // As a JSON object (proofs/witness_json.hpp), as text: the start positions and the
  // rounds as printed; `role` "counterexample" or "undecided".
  std::string json(const std::string& role) const;
};

// A claim of the theorem under one reading over the runs: `premise` the runs where it was
// decided, `violations` the proven failures, `undecided` the runs where it could not be
// decided within the rounds; the smallest counterexample and the smallest undecided run.
using PositionalTally = Tally<PositionalWitness>;
// "holds on 12 runs", "violated on 3 runs (decided on 12); smallest counterexample …"
template <> std::string Tally<PositionalWitness>::summary() const;

struct TheoremCheck : Check<PositionalWitness> {
  FixpointCheck counts; // part (1) at count level: Lemma 6.7 over the count family
  std::uint64_t runs = 0, rounds = 0;
  // `counterexample`: the smallest over the claims with positions.
};

// Under Membership::position, a proof that the assignment of a run now at `robots` never
// becomes fixed: no count vector that assign and any migrations through the non-owned ends
// of Γ can reach lets a round certify (see the .cpp). False: no proof (not: "it does").
bool never_fixed_by_counts(const mc::PositionSystem& system, const std::vector<mc::Robot>& robots);

// The default positional family: the one above.
TheoremCheck check_theorem_6_9(const Family& count_family, const PositionalFamily& positions = {},
                               const CheckOptions& options = {});

} // namespace proofs
