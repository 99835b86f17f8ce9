#pragma once
// The three curves of the Matlab simulation (seed 002 §VII, Fig. 9: "C1 covers a
// rectangular region at the lower-right corner of B, C2 covers a rectangular region at
// the top-left corner of B, and C3 is an annular ring at the center of B"), as functions
// of the grid side m and the region side b. The paper gives no sizes; ours are below and
// every size is a parameter.
//
// C1, C2: the boundary of a w × h rectangle (a closed polyline) whose outer sides run
//   `inset` in from the two sides of the corner: C1 at the lower-right corner (large x,
//   large y: y grows downward), C2 at the top-left. Defaults: w = h = max(1, ⌊m/3⌋)·b,
//   inset = b/2, so that every side runs along the middle of a row or column of regions
//   and every region it meets holds exactly b of it.
// C3: an annulus centred at (m·b/2, m·b/2): two circles, radii m·b/8 and m·b/4 by default.
// Every size is a parameter (CurveSizes; `simulate --rect-size, --rect-inset, --ring-radii`).

#include <optional>
#include <string>
#include <string_view>

#include "models/mc/curve.hpp"

namespace mc {

Curve curve_c1(int m, const Rational& b = Rational(1));
Curve curve_c1(int m, const Rational& b, const Rational& width, const Rational& height,
               const Rational& inset);
Curve curve_c2(int m, const Rational& b = Rational(1));
Curve curve_c2(int m, const Rational& b, const Rational& width, const Rational& height,
               const Rational& inset);
Curve curve_c3(int m, const Rational& b = Rational(1));
Curve curve_c3(int m, const Rational& b, const Rational& inner, const Rational& outer);

// The sizes of the three curves as functions of m: our choice, the paper gives none. The
// defaults are the sizes above.
struct CurveSizes {
  // C1, C2: width and height ⌊fraction·m⌋·b (at least b), the sides `inset` in from the
  // corner (units of b).
  Rational rect_width{1, 3}, rect_height{1, 3};
  Rational rect_inset{1, 2};
  // C3: the radii as fractions of m·b.
  Rational ring_inner{1, 8}, ring_outer{1, 4};

  // "C1, C2: floor(1/3 m) x floor(1/3 m) regions, 1/2 in from the corner; C3: radii 1/8 and
  // 1/4 of m b"
  std::string describe() const;
  // Why the sizes cannot make curves (a fraction not positive, inner >= outer, a rectangle
  // wider than the grid), or nothing.
  std::optional<std::string> invalid() const;
};

// "C1", "C2" or "C3" (case-insensitive) with these sizes; std::invalid_argument naming the
// choices otherwise, or when the curve does not fit in the deployment square.
Curve simulation_curve(std::string_view name, int m, const Rational& b = Rational(1),
                       const CurveSizes& sizes = {});

} // namespace mc
