#include "models/mc/curve_simulation.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

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

Curve simulation_curve(std::string_view name, int m, const Rational& b) {
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  if (upper == "C1")
    return curve_c1(m, b);
  if (upper == "C2")
    return curve_c2(m, b);
  if (upper == "C3")
    return curve_c3(m, b);
  throw std::invalid_argument("unknown simulation curve '" + std::string(name) +
                              "' (choose C1, C2 or C3)");
}

} // namespace mc
