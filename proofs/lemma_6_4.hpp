#pragma once
// Lemma 6.4 of seed 000 (journal) = Lemma 2 of seed 002 (conference): a region never gets
// more robots (Out) or a higher density y/q (In) than its fullest neighbour had, one round
// t -> t+1, on every instance of a family and every outcome of the round.
//
// Seed 002 (conference), §VI, line 256:
//   "Lemma 2: In every round t ≥ t0, for g, h ∈ H and h ∈ Nbrs_g: (1) If g, h ∈ Out(t),
//    y_h(t) = max_{f ∈ Nbrs_g} y_f(t), and y_g(t) < y_h(t), then y_g(t+1) ≤ y_h(t) − 1, and
//    (2) If g, h ∈ In(t), y_h(t)/q_h = max_{f ∈ Nbrs_g} y_f(t)/q_f, and
//    y_g(t)/q_g < y_h(t)/q_h, then y_g(t+1)/q_g ≤ y_h(t)/q_h − σ/q_max²."
// and its proof (lines 258–260): each neighbour sends g at most ρ2·(y_h − y_g)/2(|lower|+1)
// ≤ ρ2·(y_h − y_g)/4 (resp. ρ2·((q_g/q_h)·y_h − y_g)/4), "the total number of CNs assigned
// to VN_g in round t by all four of its neighbors is at most ρ2(y_h(t) − y_g(t))", so
// y_g(t+1) ≤ ρ2·y_h + (1 − ρ2)·y_g < y_h; for (2) likewise y_g(t+1)/q_g ≤
// (1 − ρ2)·y_g/q_g + ρ2·y_h/q_h < y_h/q_h, and "A simple calculation shows that if
// y_h(t)/q_h ≠ y_g(t)/q_g, then y_h(t)/q_h − y_g(t)/q_g ≥ σ/q_max²."
//
// Seed 000 (journal), §6.1, lines 1059–1080:
//   "LEMMA 6.4. In every round t ∈ [t2, t2 + (1 + ρ3)m²n], for u, v ∈ U and u ∈ nbrs(v):
//    (1) If u, v ∈ Out(t) and y(v, t) = max_{w ∈ nbrs(u) ∩ Out(t)} y(w, t) and
//        y(u, t) < y(v, t), then y(u, t + 1) < y(v, t).
//    (2) If u, v ∈ In(t) and y(v, t)/q_v = max_{w ∈ nbrs(u) ∩ In(t)} [y(w, t)/q_w] and
//        y(u, t)/q_u < y(v, t)/q_v, then y(u, t + 1)/q_u ≤ y(v, t)/q_v − (1 − ρ2)·σ/q_max²."
// (its proof is in an appendix the seed does not contain).
//
// The statements differ (the journal's u is the conference's g, v is h):
//   - rounds: conference every t ≥ t0; journal only t ∈ [t2, …], where Lemma 6.2 has fixed
//     In and Out and Lemma 6.3 says no region of Out assigns robots to a neighbour in In
//     (line 1044). Outside that window a boundary region (q = 0, a neighbour on the curve)
//     sends ⌊(y − k)/|In|⌋ robots to each In neighbour (Fig. 7 lines 19–22), which no
//     density bound limits: conference part (2) fails there.
//   - the maximum: conference over all of Nbrs_g (for (2): the neighbours on the curve,
//     y/q being undefined for q = 0); journal over nbrs(u) ∩ Out(t) (resp. ∩ In(t)).
//   - the gap of (2): conference σ/q_max²; journal (1 − ρ2)·σ/q_max² (weaker).
//   - both proofs count on at most four neighbours (|lower| ≥ 1 gives the /4, "all four of
//     its neighbors" gives ≤ ρ2·(…)); with the journal's 8-neighbourhood (§4.1) eight
//     senders can give g up to 2ρ2·(…). The check measures what happens.
//
// Units. q is an integer n_u in units of σ (q_u = n_u·σ). Then y/q = (y/n)/σ and
// σ/q_max² = 1/(n_max²·σ), so every inequality of (2) is the same inequality between
// y/n and 1/n_max² (robots per σ): y_g(t+1)/n_g ≤ y_h/n_h − 1/n_max². All of it is decided
// exactly, multiplied out in integers (256-bit, or arbitrary precision for a huge ρ2).
// The "simple calculation": y_h/n_h − y_g/n_g = (y_h·n_g − y_g·n_h)/(n_g·n_h); a nonzero
// integer numerator is at least 1 and n_g·n_h ≤ n_max², so a nonzero difference is at least
// 1/n_max², i.e. σ/q_max² (true; checked as stated, and as the proof uses it: between
// y_h(t)/q_h and y_g(t+1)/q_g).
//
// The journal window at round level. A claim of the journal is checked on the rounds that
// satisfy, in that round, what the window provides: In(t+1) = In(t), Out(t+1) = Out(t), and
// no robot moves from a region off the curve to one on it. A failure there is a violation
// only when the round is shown to lie in a window: with t0 = t1 = t2 = t (every
// configuration is a possible M_t0), this outcome and then the default order up to the fixed
// point (after which nothing moves) keep In and Out and never send a robot from Out to In,
// so Lemmas 6.2 (1)–(2) and 6.3 hold for every later round. Failures not so placed are
// counted apart ("undecided"), never reported as violations.
//
// Regions are active when they hold at least one robot at the start of round t
// (models/mc/README.md); every configuration of counts is a possible M_t0.

#include "proofs/family.hpp"
#include "proofs/round_lemma.hpp"

namespace proofs {

// The claims, in order: L2(1), 6.4(1), L2(2), 6.4(2) (the statements); then the proof's
// steps: "L2(1) step", "L2(2) step", "L2(2) sigma step (as stated)",
// "L2(2) sigma step (as used)".
const RoundLemma& lemma_6_4();

LemmaCheck check_lemma_6_4(const Family& family, const CheckOptions& options = {});

LemmaCheck search_lemma_6_4(const SearchOptions& options);

// Whether the round lies in a journal window (see above): nullopt if so, else why not.
std::optional<std::string> journal_window(const RoundStep& step);

} // namespace proofs
