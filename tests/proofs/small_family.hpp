#pragma once
// The small family the fixed-point lemma tests (6.5, 6.6, 6.7) pin their figures on:
// 2×2 with counts 0..4 and 3×3 with counts 0..1, every curve, k ∈ {1, 2}, ρ2 ∈ {1/2, 9/10}.

#include "proofs/family.hpp"

namespace proofs::testing {

inline Family small_family(mc::Neighbourhood nbh) {
  Family f;
  f.sides = {{2, 4}, {3, 1}};
  f.neighbourhoods = {nbh};
  f.ks = {1, 2};
  f.rho2s = {{1, 2}, {9, 10}};
  return f;
}

// The small family the round lemma tests (6.1, 6.4) pin their figures on: 1×1 with counts
// 0..3, 2×2 with counts 0..4 and 3×3 with counts 0..2, every curve, k ∈ {1, 2},
// ρ2 ∈ {1/2, 9/10}.
inline Family small_round_family(mc::Neighbourhood nbh) {
  Family f;
  f.sides = {{1, 3}, {2, 4}, {3, 2}};
  f.neighbourhoods = {nbh};
  f.ks = {1, 2};
  f.rho2s = {{1, 2}, {9, 10}};
  return f;
}

} // namespace proofs::testing
