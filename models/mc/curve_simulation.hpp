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

// "C1", "C2" or "C3" (case-insensitive) with the default sizes; std::invalid_argument
// naming the choices otherwise.
Curve simulation_curve(std::string_view name, int m, const Rational& b = Rational(1));

} // namespace mc
