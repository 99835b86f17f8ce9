#pragma once
// The assign function of seed 002 Fig. 7 (seed 001 Fig. 4; seed 000 §5.4 writes k for the
// conference's e), on counts: how many of the y(h) robots assigned to VN_h it reassigns to
// each neighbour in one round. Line numbers "line N" are those of Fig. 7.
//
//   6   if y(h) > e then
//   7     if q_h ≠ 0 then
//   8       let lower = {g ∈ In : (q_g/q_h)·y(h) > y(g)}
//   9       for each g ∈ lower
//  10         ra ← min(⌊ρ2·[(q_g/q_h)·y(h) − y(g)] / 2(|lower|+1)⌋, n − e)
//  11         update assign by reassigning ra nodes from h to g
//  12         n ← n − ra
//  13     else if In = ∅ then
//  14       let lower = {g ∈ Nbrs : y(h) > y(g)}
//  15       for each g ∈ lower
//  16         ra ← min(⌊ρ2·[y(h) − y(g)] / 2(|lower|+1)⌋, n − e)
//  17         update assign by reassigning ra nodes from h to g
//  18         n ← n − ra
//  19     else
//  20       ra ← ⌊(y(h) − e)/|In|⌋
//  21       for each g ∈ In
//  22         update assign by reassigning ra nodes from h to g
//
// with n initially y(h) (line 4) and In = {g ∈ Nbrs : q_g ≠ 0} (Fig. 6 line 10).
//
// Decisions (see models/mc/README.md, "assign and the round-level system"):
// - Counts only. Which of VN_h's robots are reassigned is irrelevant here: every robot of
//   region h is one of y(h) interchangeable counts to assign. It matters only to
//   calctarget (positions), which will choose (or enumerate) the robots.
// - A neighbour g with no robots has no VN (it is emulated by the robots in its region,
//   seed 002 §VIII), sends no vn-update, and VN_h resets V(g) to ⟨0, 0⟩ (Fig. 6 lines
//   48–50): y(g) = 0. It stays in Nbrs and, when q_g ≠ 0, in In (a constant of the
//   curve, Fig. 6 line 10), so it can be in lower and receive robots: this is how empty
//   regions are populated (seed 002 §VII starts with every robot in one corner).
// - Nbrs is the neighbourhood of the grid tiling: 4 (seed 002 §II) or 8 (seed 000 §4.1).
// - "for each g ∈ lower" (lines 9, 15) leaves the order open, and it matters: n decreases,
//   so once the cap n − e binds, the neighbours visited later get less. The default order
//   is increasing region id; assign_every_order enumerates every distinct outcome over
//   all orders. Line 21 (the boundary) has no cap, so its order does not matter.
// - Every real-valued expression is evaluated exactly: the comparison of line 8 as
//   q_g·y(h) > y(g)·q_h on integers, the floors of lines 10 and 16 as integer floors of
//   exact rationals (ρ2 a cpp_rational).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "models/mc/grid.hpp"
#include "models/mc/rational.hpp"

namespace mc {

using RobotCount = std::int64_t;
using QuantisedLength = std::int64_t; // q_u in units of σ: 0 means u is off the curve

// Bounds on the inputs, so that every product of lines 8 and 10 fits in 64 bits
// (q_g·y(h) <= 10^18): at most 10^12 robots in a region (and in total, for the round-level
// system) and q_u <= 10^6 (in units of σ).
inline constexpr RobotCount max_robots = 1'000'000'000'000;
inline constexpr QuantisedLength max_quantised_length = 1'000'000;

// The parameters assign uses: the safe number k (e in seed 002; k ∈ Z⁺, seed 000 §5.4)
// and the damping factor ρ2 ∈ (0, 1).
class AssignParams {
public:
  // Throws std::invalid_argument unless k >= 1 and 0 < rho2 < 1.
  AssignParams(RobotCount k, Rational rho2);

  RobotCount k() const { return k_; }
  const Rational& rho2() const { return rho2_; }

  // ρ2 = numerator/denominator as 64-bit integers when both fit (the fast exact path).
  bool small() const { return small_; }
  std::int64_t rho2_numerator() const { return numerator_; }
  std::int64_t rho2_denominator() const { return denominator_; }

private:
  RobotCount k_;
  Rational rho2_;
  bool small_ = false;
  std::int64_t numerator_ = 0, denominator_ = 1;
};

struct NeighbourView {
  RegionId id;
  RobotCount y;      // y(g) as VN_h knows it (0 when g has no robots: its VN is failed)
  QuantisedLength q; // q_g
};

// What VN_h knows when it runs assign (Fig. 6 lines 46–52): y(h), q_h, and y(g), q_g for
// every g ∈ Nbrs_h, in increasing id order.
struct VnView {
  RegionId h = 0;
  RobotCount y = 0;
  QuantisedLength q = 0;
  std::vector<NeighbourView> neighbours;
};

enum class AssignBranch {
  keep,               // y(h) <= e: line 6 is false, nothing is reassigned
  on_curve,           // q_h != 0: lines 7–12
  no_curve_neighbour, // q_h = 0 and In = ∅: lines 13–18
  boundary,           // q_h = 0 and In != ∅: lines 19–22
};

std::string to_string(AssignBranch branch);

struct AssignResult {
  AssignBranch branch = AssignBranch::keep;
  // lower (lines 8, 14) in the order it was processed; In (line 21) for the boundary.
  std::vector<RegionId> lower;
  // Per neighbour (indexed like VnView::neighbours): the first argument of the min of
  // lines 10/16, ⌊ρ2·[...]/2(|lower|+1)⌋, before the cap n − e; line 20's ra for the
  // boundary; 0 for neighbours outside lower.
  std::vector<RobotCount> ideal;
  // Per neighbour: how many robots h reassigns to it.
  std::vector<RobotCount> sent;

  RobotCount total_sent() const;
};

// What VN_h sees in a grid where region u has y[u] robots and quantised length q[u].
// Throws std::invalid_argument on sizes that do not match the grid or values out of bounds.
VnView vn_view(const GridTiling& grid, RegionId h, std::span<const RobotCount> y,
               std::span<const QuantisedLength> q);

// assign with lower processed in increasing region id (the default order).
AssignResult assign(const VnView& view, const AssignParams& params);

// assign with lower processed in `order`, which must be a permutation of lower (the set
// of line 8 or 14); throws std::invalid_argument when it is not. Ignored when y(h) <= e
// and on the boundary (line 21 has no cap: its order does not matter).
AssignResult assign(const VnView& view, const AssignParams& params,
                    std::span<const RegionId> order);

// Every distinct outcome (distinct `sent`) of assign over all orders of lower, sorted by
// `sent` lexicographically; each with `lower` in one order that produces it. One
// element when the order does not matter (in particular when the cap never binds).
std::vector<AssignResult> assign_every_order(const VnView& view, const AssignParams& params);

} // namespace mc
