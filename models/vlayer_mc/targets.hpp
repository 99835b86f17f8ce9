#pragma once
// What VN_u computes at phase e + 2d + 2ε (seed 000 §5.4 lines 876–965; seed 002 Fig. 7):
// assign on counts (mc::assign, default order) and calctarget on the lattice. A pure
// function, so that it is tested apart from the automaton.
//
// The curve of the first instances (README, "Discretisation"): Γ is the horizontal line
// y = b/2 through row 0, parameterised by x; Γ_u is [col·b, (col+1)·b] on it for a row-0
// region u (q_u = b in units of σ = 1), empty elsewhere (q_u = 0).
//
// Which robots are reassigned (line 11 does not say): VN_u's robots by increasing id, the
// first ra to the first g (increasing region id), as mc::Reassignment::lowest_ids.
// calctarget (Fig. 7): line 31 → o_g; line 33 → the nearest point of the closure of Γ_u
// (Γ_u = ∅: the robot keeps its position, as mc::TargetRule::off_curve); lines 35–38 →
// mc::spacing_step on the x of the robots on Γ_u, sorted by (x, id), rounded down to the
// lattice.

#include <optional>
#include <vector>

#include "models/mc/assign.hpp"
#include "models/vlayer_mc/branch_tally.hpp"
#include "models/vlayer_mc/config.hpp"

namespace vlayer_mc {

// q_u in units of σ for every region (the curve above).
std::vector<mc::QuantisedLength> curve_q(const Lattice& lattice);
// p lies on the closure of Γ_u (false where Γ_u is empty).
bool on_curve(const Lattice& lattice, RegionId u, Point p);

// P_u on the lattice as calctarget uses it (Fig. 7 lines 33–36): the x of Γ_u's ends,
// inf P_u = col·b and sup P_u = inf + b; with owned_ends (D14) only the points u owns, so
// sup P_u = inf + b − 1 unless u is in the last column. Meaningful where q_u ≠ 0.
struct CurveEnds {
  int inf, sup;
};
CurveEnds curve_ends(const Lattice& lattice, RegionId u, bool owned_ends);

// reported[p]: M_u(p) (nullopt: p ∉ dom M_u); counts[i]: V_u(nbrs(u)[i]).
// Returns the target of every p ∈ dom M_u (nullopt for the others); `branches`, when given,
// says which branches of Fig. 7 gave them.
std::vector<std::optional<Point>> compute_targets(const VlConfig& config, RegionId u,
                                                  const std::vector<std::optional<Point>>& reported,
                                                  const std::vector<int>& counts,
                                                  TargetBranches* branches = nullptr);

} // namespace vlayer_mc
