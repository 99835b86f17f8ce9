#pragma once
// Exact arithmetic for the curve code: rational square roots, floors, and numbers of the
// form a + s·√d (a, d rational, s ∈ {−1, 0, +1}) where a circle meets a grid line. Every
// comparison here is decided with no rounding.

#include <optional>

#include "models/mc/curve.hpp"

namespace mc::exact {

using Integer = BigInteger;

// √r when r ≥ 0 is the square of a rational (numerator and denominator, in lowest terms,
// are perfect squares), else nothing.
std::optional<Rational> sqrt_if_square(const Rational& r);

int sign(const Rational& r);

// |b − a|, exact when it is rational, else rounded to Real.
Real segment_length(const RationalPoint& a, const RationalPoint& b);

// a + sign·√radicand with radicand > 0 and not a rational square, or sign = 0 (then the
// number is the rational a). make() folds a square radicand into a, so the
// representation is canonical and == is equality of the numbers.
struct QuadraticIrrational {
  Rational a;
  int sign = 0;
  Rational radicand;

  static QuadraticIrrational make(const Rational& a, int sign, const Rational& radicand);
  bool rational() const { return sign == 0; }
  Real value() const;
  friend bool operator==(const QuadraticIrrational&, const QuadraticIrrational&) = default;
};

// The sign of x − c.
int compare(const QuadraticIrrational& x, const Rational& c);
// ⌊x / b⌋ for b > 0.
Integer floor_div(const QuadraticIrrational& x, const Rational& b);

} // namespace mc::exact
