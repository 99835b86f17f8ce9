#pragma once
// What Theorem 1 of seed 002 says of the assignment once it is fixed, measured at one round
// start of the conference layer (docs/design/vn-layer.md §5.3, check 6):
//
//   002:236: "the size of the set is proportional to the quantized length q_h within a
//   constant additive term 10(2m−1)/(q_min ρ2)"; Lemma 6 (002:296–298): "In every round
//   t ≥ T_stab, for g, h ∈ In(t): |y_h(t)/q_h − y_g(t)/q_g| ≤ [10(2m−1)/(q_min ρ2)]".
//   002:238 and Lemma 7 (002:304–318): the CNs in B_h, h ∈ In, "are evenly spaced on Γ_h in
//   the limit": p_i → p̄_i = p_0 + i/(n+1)·(p_{n+1} − p_0), p_0 = inf P_h, p_{n+1} = sup P_h.
//
// Decisions (models/vn_layer/README.md):
// - In at a round start: the zones with q_h ≠ 0 that hold an active CN (as
//   mc::RoundSystem::in_regions). Lemma 6 asks the VN to be active in round t, which needs
//   its CNs in rounds t − 1 and t; once the assignment is fixed the two readings agree.
// - m of a rows × cols grid: max(rows, cols), the side of the smallest square grid holding
//   it (the proof counts 2m − 1 hops across an m × m grid; fewer hops only tighten it).
// - The bound is the exact 10(2m−1)/(q_min ρ2): 002:236 prints no bracket, 002:298 a
//   bracket that may be a ceiling; a spread within the exact value is within both.
// - The parameter of a CN on Γ_h is its x (Γ is the line y = b/2 through row 0,
//   vlayer_mc/targets.hpp); P_h's ends are the ones calctarget uses (D14, owned_ends).

#include <string>
#include <vector>

#include "models/mc/assign.hpp"
#include "models/mc/rational.hpp"
#include "models/vn_layer/config.hpp"

namespace vn_layer {

// The largest |y_h/q_h − y_g/q_g| over g, h ∈ In; 0 when In has fewer than two zones.
// `counts`: the active CNs per zone; `q`: q_h per zone.
mc::Rational density_spread(const std::vector<int>& counts,
                            const std::vector<mc::QuantisedLength>& q);

// q_min: the smallest q_h ≠ 0 (0 when every q_h is 0).
mc::QuantisedLength q_min_of(const std::vector<mc::QuantisedLength>& q);

// 10(2m−1)/(q_min ρ2) for the instance (the decisions above).
mc::Rational proportionality_bound(const VnConfig& config);

// The distance to even spacing at a round start: over the zones with q_h ≠ 0 that hold two
// active CNs or more, the largest |x_i − p̄_i| between the sorted x of its CNs and n evenly
// spaced points from inf P_h to sup P_h (mc::even_spacing), in lattice units; 0 when no
// zone holds two. `where` names the zone that gives it, its CNs' x and the even ones.
// `points`: each CN's point, −1 for a failed CN.
struct SpacingGap {
  mc::Rational distance{0};
  std::string where;
};
SpacingGap spacing_gap(const VnConfig& config, const Lattice& lattice,
                       const std::vector<int>& points);

} // namespace vn_layer
