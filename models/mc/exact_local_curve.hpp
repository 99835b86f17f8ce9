#pragma once
// Exact local geometry of Γ for the positional model (calctarget, seed 002 Fig. 7 lines
// 26–38): Γ_u, Γ_u(s), Γ_u⁻¹(x) and the nearest point of Γ_u in exact rationals, so that
// robots' positions stay exact from round to round.
//
// Only polylines (open or closed) whose every segment has a rational length qualify
// (axis-parallel segments, 3-4-5 segments, …): then every grid crossing, every point
// Γ_u(s) at a rational s, and every unit direction is rational. Anything else — a circle,
// an annulus, a segment of irrational length — is refused with std::invalid_argument,
// naming the segment or component.
//
// The region decomposition, the ownership of boundary points (region_of), the convexity
// check of seed 000 §5.1 and q_u are CurveOnGrid's (models/mc/curve_local.hpp); this file
// only rebuilds each Γ_u exactly from the pieces CurveOnGrid found and checks that the two
// agree. The local parameter of region u is s ∈ [0, |A_u|], the arc length from inf P_u:
// Γ_u(s) = Γ(inf P_u + s).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "models/mc/curve.hpp"
#include "models/mc/curve_local.hpp"
#include "models/mc/grid.hpp"
#include "models/mc/rational.hpp"

namespace mc {

// A straight piece of Γ_u: Γ_u(s) = start + (s − begin)·direction for s in [begin, end].
struct ExactPiece {
  std::size_t segment = 0; // the segment of the polyline component it lies on
  Rational begin, end;     // local parameters
  RationalPoint start;     // Γ_u(begin)
  RationalPoint direction; // the segment's unit vector (rational: its length is)
};

struct ExactLocalPart {
  RegionId region = 0;
  bool empty = true; // A_u = ∅
  std::size_t component = 0;
  Rational inf;                   // inf P_u in the parameter domain of Γ (as CurveOnGrid's, exact)
  Rational length;                // |A_u| = sup P_u − inf P_u
  bool inf_owned = false;         // Γ_u(0) lies in R_u
  bool sup_owned = false;         // Γ_u(|A_u|) lies in R_u
  std::int64_t q = 0;             // q_u / σ
  std::vector<ExactPiece> pieces; // in order; one zero-length piece when |A_u| = 0
};

// The nearest point of the closure of Γ_u to a point.
struct ExactNearest {
  Rational parameter; // local, in [0, |A_u|]
  RationalPoint point;
  Rational squared_distance;
};

class ExactCurve {
public:
  // Throws std::invalid_argument when the curve has a circle or a segment of irrational
  // length ("positions need exact arc lengths: segment 2 from (0,0) to (1,1) has length
  // √2"), and whatever CurveOnGrid throws.
  ExactCurve(Curve curve, const GridTiling& tiling, const Rational& sigma,
             const Rational& b = Rational(1));

  const CurveOnGrid& on_grid() const { return on_grid_; }
  const GridTiling& grid() const { return grid_; }
  std::size_t size() const { return local_.size(); }

  const ExactLocalPart& local(RegionId u) const { return local_.at(u); }
  const Rational& length(RegionId u) const { return local(u).length; } // |A_u|
  bool meets(RegionId u) const { return !local(u).empty; }             // A_u ≠ ∅

  // Γ_u(s) for s in [0, |A_u|] (the closure: calctarget line 36 needs Γ_u(|A_u|) even when
  // the next region owns it). std::out_of_range outside, std::invalid_argument if A_u = ∅.
  RationalPoint point(RegionId u, const Rational& s) const;
  // Γ_u⁻¹(x): the local parameter of x when x lies exactly on the closure of Γ_u (the
  // smallest one when a closed curve inside one region passes x twice).
  std::optional<Rational> parameter(RegionId u, const RationalPoint& x) const;
  // The nearest point of the closure of Γ_u, squared distances compared exactly; ties go
  // to the smallest parameter, as CurveOnGrid::nearest (this fixes line 33's "choose").
  ExactNearest nearest(RegionId u, const RationalPoint& x) const;

  // The region that owns x (CurveOnGrid's rule) and the centre o_u (line 31).
  RegionId region_of(const RationalPoint& x) const { return on_grid_.region_of(x); }
  RationalPoint centre(RegionId u) const { return on_grid_.centre(u); }
  // Whether x lies in the closed square of region u.
  bool in_closure(RegionId u, const RationalPoint& x) const;

private:
  GridTiling grid_;
  CurveOnGrid on_grid_;
  std::vector<ExactLocalPart> local_;
};

} // namespace mc
