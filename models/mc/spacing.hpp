#pragma once
// calctarget on one region's curve, in parameter space: seed 002 Fig. 7 lines 34–38 (seed
// 001 Fig. 4; seed 000 §5.4, "lines 31–32" and "line 35" of its Figure 4). The robots
// assigned to VN_h that lie on Γ_h, sorted by their parameter p = Γ_h⁻¹(locM(i)) and then
// by id (line 27), move as follows:
//   line 35: the first of seq goes to Γ_h(inf P_h);
//   line 36: otherwise the last goes to Γ_h(sup P_h);
//   line 38: every other one to p + ρ1·((p_{k−1} + p_{k+1})/2 − p).
// A single robot is first (line 35 is tested before line 36), so it goes to inf P_h.
//
// All in exact rationals: the parameters, the ends of P_h and ρ1.

#include <vector>

#include "models/mc/rational.hpp"

namespace mc {

// The parameters after one round of lines 35–38, in the order of `sorted` (which must be
// sorted, ascending; ties keep their order, as the ids break them). With 0 < ρ1 ≤ 1 the
// result is sorted again: p'_{k+1} − p'_k = (1 − ρ1)·d_k + ρ1/2·(d_{k−1} + d_{k+1}) with d
// the gaps, all ≥ 0 (d_0 and d_n taken against the new ends).
std::vector<Rational> spacing_step(const std::vector<Rational>& sorted, const Rational& inf,
                                   const Rational& sup, const Rational& rho1);

// The evenly spaced parameters of n robots between the ends (seed 002 proof of Lemma 7:
// p̄_i = p_0 + i/(n+1)·(p_{n+1} − p_0) for the n interior robots, p_0 = inf, p_{n+1} = sup):
// inf, inf + (sup − inf)/(n − 1), …, sup for n ≥ 2 robots; {inf} for one.
std::vector<Rational> even_spacing(std::size_t robots, const Rational& inf, const Rational& sup);

} // namespace mc
