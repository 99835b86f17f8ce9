#pragma once
// Short names for the exact values the mc model tests write: a rational, a point, a grid.

#include <utility>

#include "models/mc/curve.hpp"
#include "models/mc/grid.hpp"

namespace mc::testing {

// (Rational(n) / d: the two-argument constructor, inlined here, made GCC 12 warn
// -Wmaybe-uninitialized inside Boost.)
inline Rational frac(long n, long d = 1) {
  return Rational(n) / d;
}
inline RationalPoint at(Rational x, Rational y) {
  return {std::move(x), std::move(y)};
}
inline GridTiling grid(int m, Neighbourhood neighbourhood = Neighbourhood::four) {
  return GridTiling(m, neighbourhood);
}

} // namespace mc::testing
