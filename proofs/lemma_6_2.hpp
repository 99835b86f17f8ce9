#pragma once
// Lemma 6.2 of seed 000 (journal; no counterpart in seed 002): In and Out become fixed, at a
// round t1, measured on every run of a family and set beside the paper's bound.
//
// Seed 000, §6.1, lines 1034–1036:
//   "LEMMA 6.2. There exists a round t1 ≥ t0 such that for every round t ∈ [t1, t1 +
//    (1 + ρ3)m²n²]: (1) In(t) = In(t1); (2) Out(t) = Out(t1); (3) Cin(t) ⊆ Cin(t + 1); and
//    (4) Cout(t+1) ⊆ Cout(t). Round t1 occurs no later than time t0 + 2m²·(1+ρ3)m²n²."
// with ρ3 = q²max/((1 − ρ2)σ) (line 1015), n the number of robots. As in fixpoint_lemma.hpp, ρ3
// is taken with σ as the unit of length and t0 = 0.
//
// The measured t1 is the least round that satisfies the statement: every round t of the
// window [t1, t1 + (1 + ρ3)m²n²] keeps In(t) = In(t1), Out(t) = Out(t1), and moves robots
// so that (3) and (4) hold. (3) and (4) are claims about which robots, read from the flow by
// robot classes (proofs/README.md, Lemma 6.1): every transfer h → g with h ∈ In(t) has
// g ∈ In(t + 1), and every transfer h → g with g ∈ Out(t + 1) has h ∈ Out(t); robots that
// stay satisfy both. After the fixed point F nothing moves and In, Out stay as at F, so
// such a t1 always exists (at the latest F) and the window is checked up to F.
//
// The proof's counting (reported, not deciding): In(t) and Out(t) only grow (Lemma 6.1), so
// they change in at most 2m² rounds — the factor 2m² of the bound.

#include <cstddef>

#include "proofs/fixpoint_lemma.hpp"

namespace proofs {

// (1 + ρ3)·m²·n^power: the windows of Lemmas 6.2 (power 2) and 6.3, 6.4 (power 1).
mc::Rational journal_window(const FixpointInstance& instance, int power);

// In(a) = In(b) and Out(a) = Out(b): the same regions hold robots (the curve is fixed).
bool same_in_out(const Counts& a, const Counts& b);

// Whether round t (t < F) keeps (3) C_in(t) ⊆ C_in(t+1) and (4) C_out(t+1) ⊆ C_out(t).
bool keeps_sets(const FixpointInstance& instance, std::size_t t);

// Whether some region of Out(t) assigns robots to a neighbour in In(t) in round t (t < F).
bool out_feeds_in(const FixpointInstance& instance, std::size_t t);

// The least t1 of the statement above.
std::size_t measured_t1(const FixpointInstance& instance);

// Claims: "6.2" t1 <= 2m²(1+ρ3)m²n² (t0 = 0, t1 measured as above); "6.2 step" the rounds
// in which In or Out changes number at most 2m² (reported).
const FixpointLemma& lemma_6_2();

// The default run: check_fixpoint_family(lemma_6_2(), family).
FixpointCheck check_lemma_6_2(const Family& family, const CheckOptions& options = {});

} // namespace proofs
