#include "models/mc/curve_numbers.hpp"

#include <stdexcept>

namespace mc::exact {

namespace {

std::optional<Integer> integer_sqrt_if_square(const Integer& n) {
  if (n < 0)
    return std::nullopt;
  Integer root = boost::multiprecision::sqrt(n);
  if (root * root != n)
    return std::nullopt;
  return root;
}

} // namespace

std::optional<Rational> sqrt_if_square(const Rational& r) {
  const auto num = integer_sqrt_if_square(boost::multiprecision::numerator(r));
  if (!num)
    return std::nullopt;
  const auto den = integer_sqrt_if_square(boost::multiprecision::denominator(r));
  if (!den)
    return std::nullopt;
  return Rational(*num, *den);
}

int sign(const Rational& r) {
  return r > 0 ? 1 : (r < 0 ? -1 : 0);
}

Real segment_length(const RationalPoint& a, const RationalPoint& b) {
  const Rational squared = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  if (const auto root = sqrt_if_square(squared))
    return Real(*root);
  return sqrt(Real(squared));
}

QuadraticIrrational QuadraticIrrational::make(const Rational& a, int s, const Rational& radicand) {
  if (radicand < 0)
    throw std::logic_error("QuadraticIrrational: negative radicand");
  if (s == 0 || radicand == 0)
    return {a, 0, Rational(0)};
  if (const auto root = sqrt_if_square(radicand))
    return {a + s * *root, 0, Rational(0)};
  return {a, s > 0 ? 1 : -1, radicand};
}

Real QuadraticIrrational::value() const {
  if (sign == 0)
    return Real(a);
  return Real(a) + sign * sqrt(Real(radicand));
}

int compare(const QuadraticIrrational& x, const Rational& c) {
  const Rational e = x.a - c; // x − c = e + sign·√d
  if (x.sign == 0)
    return sign(e);
  if (x.sign > 0) // e + √d
    return e >= 0 ? 1 : sign(x.radicand - e * e);
  return e <= 0 ? -1 : sign(e * e - x.radicand); // e − √d
}

Integer floor_div(const QuadraticIrrational& x, const Rational& b) {
  // Start from the rounded quotient and correct it with exact comparisons.
  const Real approx = x.value() / Real(b);
  Integer k = boost::multiprecision::floor(approx).convert_to<Integer>();
  Rational low = Rational(k) * b; // k·b ≤ x < k·b + b when done
  while (compare(x, low) < 0) {
    --k;
    low -= b;
  }
  while (compare(x, low + b) >= 0) {
    ++k;
    low += b;
  }
  return k;
}

} // namespace mc::exact
