#pragma once
// The curve Γ on the grid tiling: its local parts Γ_u, the lengths |A_u|, the quantised
// lengths q_u = ⌈|A_u|/σ⌉·σ, q_min, q_max, In and Out (seed 000 §5.1, seed 002 §IV), and
// the operations calctarget needs (seed 002 Fig. 7 lines 26–38): Γ_u(p), Γ_u⁻¹(x) and the
// nearest point of Γ_u.
//
// Who owns a boundary point (seed 002 §III: "Each boundary point of a square is
// unambiguously assigned to one zone"): region (row, col) is the half-open square
// [col·b, (col+1)·b) × [row·b, (row+1)·b), except that the last column and the last row
// also own the far side x = m·b, y = m·b of the deployment square. So a point on an
// interior vertical grid line belongs to the region on its right (east), a point on an
// interior horizontal line to the region below it (south; y grows downward), and a grid
// vertex to the region south-east of it. region_of() is this rule.
//
// The paper's assumption (seed 000 §5.1: "We assume that A_u is convex for every region
// u"; seed 002 §IV: "We assume that P_h is convex") is checked: a curve that enters a
// region twice, or meets a region with two of its components, is rejected with
// std::invalid_argument naming the region. Under the ownership rule this includes
// tangencies: a curve that touches a grid line from one side at a single point leaves
// that point to the other region.
//
// Closed components have no natural first point, so the origin of Γ on a closed
// component is chosen where it is needed: at the first point (in the component's
// natural order) where Γ passes into a region that owns that point. Then no P_u wraps
// around the origin. A closed component inside one region keeps its natural origin.
// The parameter domain of Γ is [0, L] for an open polyline and the concatenation of the
// components' [offset_c, offset_c + L_c) for closed ones.
//
// Exactness. q_u needs the exact ceiling of |A_u|/σ (σ rational). On a polyline every
// piece of A_u has length t·√Q with t and Q rational, Q the squared length of its segment:
// when every Q is a rational square (axis-parallel segments, 3-4-5 triangles, …) |A_u| is
// a rational and the ceiling is computed exactly with cpp_rational. Otherwise the sum of
// positive multiples of square roots is irrational (square roots of distinct square-free
// integers are linearly independent over Q, and no coefficient can cancel since all are
// positive), and circle arcs give transcendental lengths (Baker's theorem), so |A_u|/σ is
// never an integer: it is computed in 100-digit binary floating point (Real) and the
// ceiling is taken when |A_u|/σ is farther than 10^-70·(1 + |A_u|/σ) from every integer.
// That margin is about 30 orders of magnitude above the rounding error of the computation
// (each +, −, ×, ÷, √ and rational conversion is within 1 ulp ≈ 3·10^-101 relative; sin,
// cos, atan2 within a few ulps; a curve here has far fewer than 10^6 pieces). Closer
// than that, PrecisionError is thrown rather than a guess. The same certified rounding
// decides the order of the points where a circle meets grid lines (coincidences are
// decided exactly) and the region of each open arc between them.

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/mc/curve.hpp"
#include "models/mc/grid.hpp"

namespace mc {

// A quantity too close to a decision boundary for the certified 100-digit arithmetic.
class PrecisionError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The margin below which a certified Real comparison refuses to decide: 10^-70.
const Real& certification_margin();

// "region 5 (row 1, col 2)"
std::string describe_region(RegionId u, int m);

// |A_u|: a rational part, plus Σ c·√d over oblique polyline pieces (c, d rational, d not
// a rational square), plus Σ r·Δθ over circle arcs (kept as a rounded Real).
class ArcLength {
public:
  // A piece of a segment: `fraction` of a segment whose squared length is `squared`.
  void add_segment_piece(const Rational& fraction, const Rational& squared);
  void add_arc(const Rational& radius, const Real& angle);
  void add(const ArcLength& other);

  // Whether the length is a rational known exactly (then rational() is its value).
  bool exact() const { return surds_.empty() && arc_count_ == 0; }
  const Rational& rational() const { return rational_; }
  Real value() const;
  bool zero() const { return exact() && rational_ == 0; }

  // ⌈|A_u| / σ⌉, exactly; throws PrecisionError (naming `what`) when the rounded value is
  // within the certification margin of an integer, and std::invalid_argument when it
  // does not fit in 62 bits.
  std::int64_t quanta(const Rational& sigma, const std::string& what) const;

  // "3/10" when exact, else 25 significant digits followed by "…".
  std::string to_string() const;

private:
  Rational rational_ = 0;
  std::map<Rational, Rational> surds_; // radicand → coefficient
  Real arcs_ = 0;
  std::size_t arc_count_ = 0;
};

// Γ_u, the local part of Γ in region u.
struct LocalPart {
  RegionId region = 0;
  bool empty = true; // A_u = ∅ (then everything below is 0)
  std::size_t component = 0;
  Real inf = 0, sup = 0;  // P_u = A_u is the interval from inf to sup, ends as below
  bool inf_owned = false; // Γ(inf) lies in R_u (is owned by u)
  bool sup_owned = false; // Γ(sup) lies in R_u; false when Γ leaves u across a boundary
                          // point owned by the next region
  ArcLength length;       // |A_u| = sup − inf
  std::int64_t q = 0;     // q_u / σ = ⌈|A_u| / σ⌉
  Real natural_begin = 0; // the component's natural parameter at inf
};

// The nearest point of Γ_u to a point: its parameter p, Γ_u(p), and the distance.
struct NearestPoint {
  Real parameter;
  Point point;
  Real distance;
};

class CurveOnGrid {
public:
  // Γ on the m×m tiling of side b, quantised with σ. Throws std::invalid_argument when
  // σ or b is not positive, the curve leaves [0, m·b]², or some A_u is not an interval;
  // PrecisionError as above.
  CurveOnGrid(Curve curve, const GridTiling& tiling, const Rational& sigma,
              const Rational& b = Rational(1));

  const Curve& curve() const { return curve_; }
  int m() const { return m_; }
  const Rational& b() const { return b_; }
  const Rational& sigma() const { return sigma_; }
  std::size_t size() const { return local_.size(); }

  // The domain of Γ: [0, length()] (open polyline) or [0, length()) (closed components).
  Real length() const { return curve_.length(); }
  // The component's first parameter in the domain of Γ, and where (in its natural
  // parameter) Γ starts on it.
  const Real& offset(std::size_t component) const { return offsets_[component]; }
  const Real& origin(std::size_t component) const { return origins_[component]; }

  const LocalPart& local(RegionId u) const { return local_.at(u); }
  // q_u / σ for every region, by RegionId; and as rows (row 0 at the top), as in the JSON
  // of `tioa-check round`.
  const std::vector<std::int64_t>& q() const { return q_; }
  std::int64_t q(RegionId u) const { return q_.at(u); }
  std::vector<std::vector<std::int64_t>> q_matrix() const;
  std::int64_t q_min() const { return q_min_; } // least non-zero q_u / σ
  std::int64_t q_max() const { return q_max_; }
  const std::vector<RegionId>& in() const { return in_; }   // {u : q_u ≠ 0}, increasing
  const std::vector<RegionId>& out() const { return out_; } // the rest

  // Γ(p) for p in the domain of Γ; std::out_of_range outside it.
  Point point(const Real& p) const;
  // Γ_u(p) for p in [inf P_u, sup P_u] (the closure, so that Γ_u(sup P_u) is defined as
  // calctarget's line 36 needs even when that point is owned by the next region). A p
  // within the certification margin outside is clamped; farther: std::out_of_range.
  // std::invalid_argument when A_u is empty.
  Point point(RegionId u, const Real& p) const;
  // Γ_u⁻¹(x): the parameter of x on the closure of Γ_u, if x lies within `tolerance` of it.
  std::optional<Real> parameter(RegionId u, const Point& x,
                                const Real& tolerance = Real("1e-50")) const;
  // The point of the closure of Γ_u nearest to x. Several nearest points (distances equal
  // within the certification margin, e.g. x the centre of a circle): the one with the
  // SMALLEST parameter. This fixes calctarget's "choose" (seed 002 Fig. 7 line 33).
  NearestPoint nearest(RegionId u, const Point& x) const;

  // The region that owns a point, by the rule above: exact for rational points, by
  // rounding for Real ones (a Real point within rounding of a grid line may go either way).
  RegionId region_of(const RationalPoint& x) const;
  RegionId region_of(const Point& x) const;
  // The centre o_u of region u (calctarget line 31).
  RationalPoint centre(RegionId u) const;

  // The q matrix, rows top to bottom, '.' for 0 (for messages and documentation).
  std::string format_q() const;

private:
  Curve curve_;
  int m_;
  Rational b_, sigma_;
  std::vector<Real> offsets_, origins_;
  std::vector<LocalPart> local_;
  std::vector<std::int64_t> q_;
  std::int64_t q_min_ = 0, q_max_ = 0;
  std::vector<RegionId> in_, out_;

  Real natural(std::size_t component, const Real& relative) const;
  std::size_t component_at(const Real& p) const;
};

} // namespace mc
