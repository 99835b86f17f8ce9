#include "models/mc/spacing.hpp"

namespace mc {

std::vector<Rational> spacing_step(const std::vector<Rational>& sorted, const Rational& inf,
                                   const Rational& sup, const Rational& rho1) {
  std::vector<Rational> next(sorted.size());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    if (k == 0)
      next[k] = inf; // line 35
    else if (k + 1 == sorted.size())
      next[k] = sup; // line 36
    else             // line 38
      next[k] = sorted[k] + rho1 * ((sorted[k - 1] + sorted[k + 1]) / 2 - sorted[k]);
  }
  return next;
}

std::vector<Rational> even_spacing(std::size_t robots, const Rational& inf, const Rational& sup) {
  if (robots == 1)
    return {inf};
  std::vector<Rational> points(robots);
  for (std::size_t i = 0; i < robots; ++i)
    points[i] =
        inf + (sup - inf) * Rational(static_cast<long long>(i), static_cast<long long>(robots - 1));
  return points;
}

} // namespace mc
