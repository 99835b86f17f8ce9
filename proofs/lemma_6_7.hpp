#pragma once
// Lemma 6.7 of seed 000 (journal) = Lemma 6 of seed 002 (conference): at the fixed point
// the robots of the In regions are proportional to q within an additive term, measured
// exactly on every run of a family beside the paper's bound.
//
// Seed 002 (conference), §VI, line 296:
//   "Lemma 6: In every round t ≥ T_stab, for g, h ∈ In(t):
//      | y_h(t)/q_h − y_g(t)/q_g | ≤ [ 10(2m − 1) / (q_min ρ2) ]."
// Seed 000 (journal), §6.1, line 1106: the same, "for u, v ∈ In(t)".
// The proof (seed 002): for neighbours g, h ∈ In, line 10 of Fig. 7 leaves
// ρ2(q_g/q_h·y_h − y_g) ≤ 2(|lower_h| + 1) ≤ 10 "since |lower_h(t)| ≤ 4", so
// |y_h/q_h − y_g/q_g| ≤ 10/(q_g ρ2) ≤ 10/(q_min ρ2); induction over at most 2m − 1 hops.
//
// Rounds t ≥ T_stab all have the counts of the fixed point M_F (FixpointRun, default order),
// so the claim is checked on M_F. Units: q_u = n_u·σ, so y/q = (y/n_u)/σ and the bound is
// 10(2m − 1)/(n_min ρ2)/σ: the claim is the same inequality between y/n_u and
// 10(2m − 1)/(n_min ρ2), decided exactly (rationals). q_min is the least non-zero q of the
// grid. The brackets are read as grouping: the exact value is the bound (a ceiling would
// only weaken it).
//
// With 8 neighbours |lower_h| can be 8, and 2(8 + 1) = 18 > 10: the neighbour step of the
// proof ("6.7 step", reported, not deciding) is measured on every pair of neighbouring In
// regions, not assumed.

#include "proofs/fixpoint_lemma.hpp"

namespace proofs {

// Claims: "6.7" max over u, v ∈ In of |y_u/q_u − y_v/q_v| ≤ 10(2m−1)/(q_min ρ2) at the fixed
// point (premise: |In| ≥ 2); "6.7 step" the same over neighbouring u, v ∈ In ≤
// 10/(q_min ρ2) (reported).
const FixpointLemma& lemma_6_7();

// The default run: check_lemma_6_7(fixpoint_family(nbh)).
FixpointCheck check_lemma_6_7(const Family& family, const CheckOptions& options = {});

} // namespace proofs
