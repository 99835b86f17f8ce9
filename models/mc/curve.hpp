#pragma once
// The target curve Γ of the motion-coordination problem (seed 000 §5.1, seed 002 §IV):
// a simple curve in the deployment square, parameterised by arc length.
//
// Coordinates are those of the deployment square [0, m·b]² of the grid tiling
// (models/mc/grid.hpp): x grows to the right and y grows DOWNWARD, so that row 0 of the
// tiling is the top strip 0 ≤ y < b, as in the printed q and robot matrices.
//
// A curve is made of components: one polyline (open or closed) with rational vertices,
// or several closed components (polylines or circles; an annulus is two concentric
// circles, seed 002 §VII's C3). This file knows only the geometry and each component's
// own ("natural") arc-length parameter; where the grid puts the origin of a closed
// component, which region owns which point, |A_u| and q_u are in curve_local.hpp.

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "models/mc/rational.hpp"

namespace mc {

// 100 significant decimal digits: the certified computations of curve_local.cpp say how
// close to a decision they may come.
using Real = boost::multiprecision::cpp_bin_float_100;

struct RationalPoint {
  Rational x, y;
  friend bool operator==(const RationalPoint&, const RationalPoint&) = default;
};

struct Point {
  Real x, y;
};

Point to_point(const RationalPoint& p);
// "(x,y)", exact, as messages and logs write a point.
std::string to_string(const RationalPoint& p);
Real distance(const Point& a, const Point& b);

// Segments between consecutive vertices; a closed polyline also joins the last vertex to
// the first. The natural parameter starts at vertices[0] and follows the vertex order.
struct Polyline {
  std::vector<RationalPoint> vertices;
  bool closed = false;
};

// The natural parameter s starts at (cx + r, cy) and turns towards +y: with y downward
// that is clockwise on the screen. Γ(s) = (cx + r·cos(s/r), cy + r·sin(s/r)).
struct Circle {
  RationalPoint centre;
  Rational radius;
};

using Component = std::variant<Polyline, Circle>;

class Curve {
public:
  // Throws std::invalid_argument (one line) unless the curve is simple: no zero-length
  // segment, no segment meeting a non-adjacent one, no backtracking at a vertex, no two
  // components meeting, a positive radius, at least 2 vertices (3 when closed); and
  // unless every component is closed when there are several (the parameter domain of
  // Γ is then the concatenation of the components' [0, L_i)).
  explicit Curve(std::vector<Component> components, std::string name = "");

  static Curve polyline(std::vector<RationalPoint> vertices, bool closed = false);
  // The boundary of the axis-parallel rectangle with these opposite corners, as a closed
  // polyline from `corner` clockwise on the screen (right, down, left, up).
  static Curve rectangle(const RationalPoint& corner, const RationalPoint& opposite);
  static Curve circle(const RationalPoint& centre, const Rational& radius);
  // Two concentric circles, the inner one first; inner < outer.
  static Curve annulus(const RationalPoint& centre, const Rational& inner, const Rational& outer);

  const std::string& name() const { return name_; }
  const std::vector<Component>& components() const { return components_; }
  std::size_t component_count() const { return components_.size(); }
  bool closed(std::size_t component) const;

  // Arc length of one component and of the whole curve (rounded to Real).
  const Real& length(std::size_t component) const { return lengths_[component]; }
  Real length() const;

  // The point at natural parameter s of a component, s in [0, length(component)]
  // (clamped into that range; for closed components s = length is the start again).
  Point point(std::size_t component, const Real& s) const;

  // The natural parameter at which segment j of a polyline component starts.
  const Real& segment_start(std::size_t component, std::size_t j) const {
    return segment_starts_[component][j];
  }

  // The smallest and largest x and y of the curve (exact): for the check that it lies
  // in the deployment square.
  RationalPoint lower_corner() const;
  RationalPoint upper_corner() const;

private:
  std::vector<Component> components_;
  std::string name_;
  std::vector<Real> lengths_;
  std::vector<std::vector<Real>> segment_starts_; // polylines only
};

// The segments of a polyline component, in order (the closing one included).
std::size_t segment_count(const Polyline& polyline);
RationalPoint segment_begin(const Polyline& polyline, std::size_t j);
RationalPoint segment_end(const Polyline& polyline, std::size_t j);

} // namespace mc
