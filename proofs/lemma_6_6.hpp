#pragma once
// Lemma 6.6 of seed 000 (journal) = Lemmas 4 and 5 of seed 002 (conference): the sets of
// robots of the In regions become fixed, at a round T_stab, measured on every run of a
// family beside the journal's bound; and the number of robots left off the curve, beside
// the conference's explicit bound.
//
// Seed 002 (conference), §VI, lines 286, 290:
//   "Lemma 4: There exists a round T_stab ≥ T_out such that in every round t ≥ T_stab, the
//    set of CNs assigned to VN_h, h ∈ In, is unchanged."          (no bound on T_stab)
//   "Lemma 5: In every round t ≥ T_out, |C_out(t)| = O(m³)." with, at the end of its proof,
//   "|C_out| ≤ (e + 4)(2m − 1)m + 10m²(2m − 1)/ρ2 = O(m³)".
// Seed 000 (journal), §6.1, line 1096:
//   "LEMMA 6.6. There exists a round Tstab ∈ [Tout, Tout + ρ3m²n] such that in every round
//    t ≥ Tstab, the set of CNs assigned to VNu, u ∈ In, is unchanged. Further, in every
//    round t ≥ Tout, |Cout(t)| = O(m³)."
//
// The journal puts the |C_out| bound in this lemma, so the conference's explicit form is
// checked here (claim "L5", k for e). From T_out on no robot leaves or joins an Out region,
// so |C_out(t)| = |C_out(T_out)| for every t ≥ T_out: it is measured at T_out. The claim
// is taken on grids with a curve (some q ≠ 0): without one no region is a boundary region,
// nothing ever leaves Out and |C_out| = n for every n, which the proof's induction from the
// boundary does not cover; that case is reported as "L5 no curve" (not deciding).
//
// T_stab is FixpointRun::t_stab, the first round ≥ T_out from which no robot leaves or
// joins an In region (seed 002 line 294, seed 000 line 1101: "the first round after Tout at
// which the property holds"); ρ3 and the chained bound on T_out as in proofs/lemma_6_5.hpp
// (σ the unit of length). Default order of run_to_fixpoint.
//
// The proof of Lemma 5 uses that a boundary region has at most 4 neighbours on the curve
// (y_g < 4 + e) and |lower| ≤ 4: with 8 neighbours both can be 8. The step "y_g < |In_g| +
// e ≤ 4 + e" on every boundary region at T_out is reported beside the claim (claim "L5
// step", not deciding the verdict): measured, not assumed.

#include "proofs/fixpoint_lemma.hpp"

namespace proofs {

// Claims: "6.6" T_stab − T_out ≤ ρ3m²n; "6.6 total" T_stab ≤ the chain bound of T_out +
// ρ3m²n; "L5" |C_out(T_out)| ≤ (k+4)(2m−1)m + 10m²(2m−1)/ρ2; "L5 step" (reported) the
// largest count of a boundary Out region at T_out ≤ k + 3 (< 4 + k); "L5 no curve"
// (reported) the L5 bound on grids without a curve.
const FixpointLemma& lemma_6_6();

// The default run: check_lemma_6_6(fixpoint_family(nbh)).
FixpointCheck check_lemma_6_6(const Family& family, const CheckOptions& options = {});

} // namespace proofs
