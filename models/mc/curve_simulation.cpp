#include "models/mc/curve_simulation.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace mc {

namespace {

void check_side(int m, const Rational& b) {
  if (m < 1)
    throw std::invalid_argument("grid side m must be at least 1, not " + std::to_string(m));
  if (b <= 0)
    throw std::invalid_argument("region side b must be positive, not " + b.str());
}

Rational default_side(int m, const Rational& b) {
  return std::max(1, m / 3) * b;
}

Curve named(Curve curve, const std::string& name) {
  return Curve(curve.components(), name);
}

} // namespace

Curve curve_c1(int m, const Rational& b) {
  return curve_c1(m, b, default_side(m, b), default_side(m, b), b / 2);
}

Curve curve_c1(int m, const Rational& b, const Rational& width, const Rational& height,
               const Rational& inset) {
  check_side(m, b);
  const Rational right = m * b - inset, bottom = m * b - inset;
  return named(Curve::rectangle({right - width, bottom - height}, {right, bottom}), "C1");
}

Curve curve_c2(int m, const Rational& b) {
  return curve_c2(m, b, default_side(m, b), default_side(m, b), b / 2);
}

Curve curve_c2(int m, const Rational& b, const Rational& width, const Rational& height,
               const Rational& inset) {
  check_side(m, b);
  return named(Curve::rectangle({inset, inset}, {inset + width, inset + height}), "C2");
}

Curve curve_c3(int m, const Rational& b) {
  return curve_c3(m, b, m * b / 8, m * b / 4);
}

Curve curve_c3(int m, const Rational& b, const Rational& inner, const Rational& outer) {
  check_side(m, b);
  const Rational middle = m * b / 2;
  return named(Curve::annulus({middle, middle}, inner, outer), "C3");
}

namespace {

// ⌊fraction·m⌋·b, at least b.
Rational scaled_side(const Rational& fraction, int m, const Rational& b) {
  const Rational regions = fraction * m;
  const auto whole = numerator(regions) / denominator(regions);
  return std::max<Rational>(1, Rational(whole)) * b;
}

} // namespace

std::string CurveSizes::describe() const {
  return "C1, C2: floor(" + to_string(rect_width) + " m) x floor(" + to_string(rect_height) +
         " m) regions (at least 1), " + to_string(rect_inset) + " in from the corner; C3: radii " +
         to_string(ring_inner) + " and " + to_string(ring_outer) + " of m b";
}

std::optional<std::string> CurveSizes::invalid() const {
  for (const Rational* r : {&rect_width, &rect_height, &ring_inner, &ring_outer})
    if (*r <= 0)
      return "every size must be positive, not " + to_string(*r);
  if (rect_width > 1 || rect_height > 1)
    return "a rectangle's side is a fraction of m of at most 1, not " +
           to_string(std::max(rect_width, rect_height));
  if (rect_inset < 0)
    return "the inset must be >= 0, not " + to_string(rect_inset);
  if (ring_inner >= ring_outer)
    return "the inner radius " + to_string(ring_inner) + " must be smaller than the outer " +
           to_string(ring_outer);
  if (ring_outer > Rational(1, 2))
    return "the outer radius " + to_string(ring_outer) + " of m b leaves the square (at most 1/2)";
  return std::nullopt;
}

Curve simulation_curve(std::string_view name, int m, const Rational& b, const CurveSizes& sizes) {
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  if (const auto why = sizes.invalid())
    throw std::invalid_argument("curve sizes: " + *why);
  check_side(m, b);
  const Rational width = scaled_side(sizes.rect_width, m, b);
  const Rational height = scaled_side(sizes.rect_height, m, b);
  const Rational inset = sizes.rect_inset * b;
  if (upper == "C1" || upper == "C2") {
    if (inset + std::max(width, height) > m * b)
      throw std::invalid_argument(fmt::format(
          "curve sizes: the {} rectangle, {} x {} and {} in, does not fit in the {} x {} square",
          upper, to_string(width), to_string(height), to_string(inset), m, m));
    return upper == "C1" ? curve_c1(m, b, width, height, inset)
                         : curve_c2(m, b, width, height, inset);
  }
  if (upper == "C3")
    return curve_c3(m, b, sizes.ring_inner * m * b, sizes.ring_outer * m * b);
  throw std::invalid_argument("unknown simulation curve '" + std::string(name) +
                              "' (choose C1, C2 or C3)");
}

} // namespace mc
