#pragma once
// Lemma 6.5 of seed 000 (journal) = Lemma 3 of seed 002 (conference): the sets of robots
// of the Out regions become fixed, at a round T_out, measured on every run of a family and
// set beside the paper's bound.
//
// Seed 002 (conference), §VI, line 264:
//   "Lemma 3: There exists a round T_out ≥ t0 such that in any round t ≥ T_out, the set of
//    CNs assigned to VN_h, h ∈ Out(t), is unchanged."            (no bound on T_out)
// Seed 000 (journal), §6.1, lines 1034–1036, 1044–1045, 1086–1087:
//   "LEMMA 6.2. There exists a round t1 ≥ t0 such that […] Round t1 occurs no later than
//    time t0 + 2m²·(1 + ρ3)m²n²."
//   "LEMMA 6.3. There exists some round t2 ∈ [t1, t1 + (1 + ρ3)m²n²] such that […]"
//   "LEMMA 6.5. There exists a round Tout ∈ [t2, t2 + m²n] such that in any round
//    t ≥ Tout, the set of CNs assigned to VNu, u ∈ Out(t), is unchanged."
// with (line 1015) "ρ3 ≜ q²max/(1 − ρ2)σ". Chained, with t0 = 0:
//   T_out ≤ 2m²(1 + ρ3)m²n² + (1 + ρ3)m²n² + m²n,
// n the number of robots. ρ3 is not dimensionless (a length); it is taken with σ as the
// unit of length, so ρ3 = n_max²/(1 − ρ2) with q_max = n_max·σ (and ρ3 = 0 without a curve,
// where the paper's "ρ3 > 1" fails). Every bound is an exact rational.
//
// T_out is FixpointRun::t_out (models/mc/round.hpp): the first round from which no robot
// leaves or joins an Out(t) region, "the first round after t0 at which the property holds"
// (seed 002 line 284, seed 000 line 1088). Runs use the default order of run_to_fixpoint
// (every VN's lower set by increasing region id); the lemma claims every run.
//
// The run, the measurement and the check are those of every fixed-point lemma
// (proofs/fixpoint_lemma.hpp).

#include "proofs/fixpoint_lemma.hpp"

namespace proofs {

// Claims: "6.5" T_out ≤ 2m²(1+ρ3)m²n² + (1+ρ3)m²n² + m²n (the chain of Lemmas 6.2, 6.3,
// 6.5), and "6.5 step" T_out − t2 ≤ m²n with t2 the first round from which no Out region
// sends to an In region and In, Out stay fixed (the journal's window, measured; reported).
const FixpointLemma& lemma_6_5();

// The chained bound on T_out: 2m²(1+ρ3)m²n² + (1+ρ3)m²n² + m²n (t0 = 0).
mc::Rational t_out_bound(const FixpointInstance& instance);

// The default run: check_fixpoint_family(lemma_6_5(), fixpoint_family(nbh)).
FixpointCheck check_lemma_6_5(const Family& family, const CheckOptions& options = {});

} // namespace proofs
