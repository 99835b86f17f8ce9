#pragma once
// Lemma 6.1 of seed 000 (journal) = Lemma 1 of seed 002 (conference): basic facts about
// the assign function, one round t -> t+1, checked on every instance of a family and every
// outcome of the round (every order of every lower set).
//
// Seed 000 (journal), §6.1, lines 1028–1030:
//   "LEMMA 6.1. In every round t ≥ t0: (1) If y(u, t) ≥ k for some u ∈ U, then
//    y(u, t + 1) ≥ k; (2) In(t) ⊆ In(t + 1); (3) Out(t) ⊆ Out(t + 1)."
// Seed 002 (conference), §VI, line 242:
//   "Lemma 1: In every round t ≥ t0: (1) If y_h(t) ≥ e for some h ∈ H, then
//    y_h(t+1) ≥ e, (2) In(t) ⊆ In(t+1), (3) Out(t) ⊆ Out(t+1), (4) C_in(t) ⊆ C_in(t+1),
//    and (5) C_out(t+1) ⊆ C_out(t)."
//
// The two statements differ: the journal has only parts (1)–(3) (k for e); parts (4) and
// (5) moved to its Lemma 6.2 (3)–(4) (line 1034), which claims them only for rounds
// t ∈ [t1, t1 + (1 + ρ3)m²n²], once In and Out are fixed. Here (4) and (5) are checked as
// the conference states them: in every round t ≥ t0.
//
// Definitions (seed 000 lines 995–1005, seed 002 line 230): In(t) / Out(t) are the VNs
// active in round t with q_u ≠ 0 / q_u = 0; C_in(t) / C_out(t) are the active CNs located
// in regions of In(t) / Out(t) at the beginning of round t. At round level (models/mc/
// README.md) a VN is active in round t when its region holds at least one robot at the
// start of round t, every robot is active (no failures from t0 on), and since failures and
// recoveries before t0 are free, every configuration of counts is a possible M_t0: a
// one-step check over all configurations covers "every round t ≥ t0".
//
// How each part reduces to counts and flows. A round moves robots along its Flow: a robot of
// region h at t is at t+1 either still in h (one of the M_t[h] − sent(h) that stay) or in g
// (one of the flow(h, g) sent there). Which robots are sent is not fixed by assign, so a
// set claim must hold for every choice: it holds iff it holds for every *class* h -> g with
// a positive number of robots (h -> h for those that stay).
//   (1) for every u with M_t[u] ≥ k: M_{t+1}[u] ≥ k.
//   (2) for every u ∈ In(t): M_{t+1}[u] ≥ 1 (q_u ≠ 0 is a constant), i.e. u ∈ In(t+1).
//   (3) for every u ∈ Out(t): M_{t+1}[u] ≥ 1.
//   (4) C_in(t) ⊆ C_in(t+1): every class h -> g with h ∈ In(t) has g ∈ In(t+1) — no robot
//       goes from an In region to a region off the curve (and one that stays in h keeps
//       h in In(t+1)).
//   (5) C_out(t+1) ⊆ C_out(t): every class h -> g with g ∈ Out(t+1) has h ∈ Out(t) — no
//       robot arrives in an Out region from a region on the curve.

#include "proofs/family.hpp"
#include "proofs/round_lemma.hpp"

namespace proofs {

// The claims, in order: 6.1(1), 6.1(2), 6.1(3), L1(4), L1(5).
const RoundLemma& lemma_6_1();

// The exhaustive check over a family (Family::standard(nbh) is the default run).
LemmaCheck check_lemma_6_1(const Family& family, const CheckOptions& options = {});

// The seeded random search.
LemmaCheck search_lemma_6_1(const SearchOptions& options);

} // namespace proofs
