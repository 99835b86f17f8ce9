#pragma once
// Lemma 6.3 of seed 000 (journal; no counterpart in seed 002): the regions off the curve
// stop assigning robots to their neighbours on the curve, from a round t2, measured on every
// run of a family and set beside the paper's bound.
//
// Seed 000, §6.1, lines 1044–1045:
//   "LEMMA 6.3. There exists some round t2 ∈ [t1, t1 + (1 + ρ3)m²n²] such that for every
//    round t ∈ [t2, t2 + (1 + ρ3)m²n]: If u ∈ Out(t) and v ∈ In(t) and if u and v are
//    neighboring regions, then u does not assign any clients to v in round t."
// with t1 the round of Lemma 6.2 (lemma_6_2.hpp: the least t1 that satisfies it).
//
// The measured t2 is the least round ≥ t1 such that in no round of [t2, t2 + (1 + ρ3)m²n]
// does a region of Out(t) assign robots to a neighbour in In(t) (a neighbour with robots on
// the curve; assign sends only to neighbours). It always exists: after the fixed point F
// nothing moves. Units and t0 = 0 as in fixpoint_lemma.hpp.

#include <cstddef>

#include "proofs/lemma_6_2.hpp"

namespace proofs {

// The least t2 of the statement, given t1.
std::size_t measured_t2(const FixpointInstance& instance, std::size_t t1);

// Claims: "6.3" t2 − t1 <= (1+ρ3)m²n²; "6.3 from t0" t2 <= 2m²(1+ρ3)m²n² + (1+ρ3)m²n²
// (Lemmas 6.2 and 6.3 chained, t0 = 0).
const FixpointLemma& lemma_6_3();

// The default run: check_fixpoint_family(lemma_6_3(), family).
FixpointCheck check_lemma_6_3(const Family& family, const CheckOptions& options = {});

} // namespace proofs
