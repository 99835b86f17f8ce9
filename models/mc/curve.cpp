#include "models/mc/curve.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/mc/curve_numbers.hpp"

namespace mc {

Point to_point(const RationalPoint& p) {
  return {Real(p.x), Real(p.y)};
}

std::string to_string(const RationalPoint& p) {
  return "(" + to_string(p.x) + "," + to_string(p.y) + ")";
}

Real distance(const Point& a, const Point& b) {
  const Real dx = a.x - b.x, dy = a.y - b.y;
  return sqrt(dx * dx + dy * dy);
}

std::size_t segment_count(const Polyline& polyline) {
  return polyline.closed ? polyline.vertices.size() : polyline.vertices.size() - 1;
}

RationalPoint segment_begin(const Polyline& polyline, std::size_t j) {
  return polyline.vertices[j];
}

RationalPoint segment_end(const Polyline& polyline, std::size_t j) {
  return polyline.vertices[(j + 1) % polyline.vertices.size()];
}

namespace {

std::string where(const std::string& name) {
  return name.empty() ? "curve" : "curve " + name;
}

// Exact predicates on rational points (the simplicity checks decide with no rounding).
int orientation(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c) {
  const Rational cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
}

// c lies in the bounding box of a, b (used once a, b, c are known to be collinear).
bool within_box(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

bool segments_meet(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c,
                   const RationalPoint& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) // they cross, or one touches the other
    return true;
  if (o1 == 0 && within_box(a, b, c))
    return true;
  if (o2 == 0 && within_box(a, b, d))
    return true;
  if (o3 == 0 && within_box(c, d, a))
    return true;
  if (o4 == 0 && within_box(c, d, b))
    return true;
  return false;
}

Rational squared_distance(const RationalPoint& a, const RationalPoint& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

bool segment_meets_circle(const RationalPoint& a, const RationalPoint& b, const Circle& circle) {
  const RationalPoint& c = circle.centre;
  const Rational r2 = circle.radius * circle.radius;
  const Rational len2 = squared_distance(a, b);
  Rational t = ((c.x - a.x) * (b.x - a.x) + (c.y - a.y) * (b.y - a.y)) / len2;
  t = std::clamp(t, Rational(0), Rational(1));
  const RationalPoint nearest{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  const Rational nearest2 = squared_distance(nearest, c);
  const Rational farthest2 = std::max(squared_distance(a, c), squared_distance(b, c));
  return nearest2 <= r2 && r2 <= farthest2;
}

bool circles_meet(const Circle& p, const Circle& q) {
  const Rational d2 = squared_distance(p.centre, q.centre);
  const Rational diff = p.radius - q.radius, sum = p.radius + q.radius;
  return diff * diff <= d2 && d2 <= sum * sum;
}

void check_polyline(const Polyline& polyline, const std::string& name) {
  const std::size_t n = polyline.vertices.size();
  if (n < (polyline.closed ? 3u : 2u))
    throw std::invalid_argument(where(name) + ": a " + (polyline.closed ? "closed" : "open") +
                                " polyline needs at least " + (polyline.closed ? "3" : "2") +
                                " vertices, not " + std::to_string(n));
  const std::size_t segments = segment_count(polyline);
  for (std::size_t j = 0; j < segments; ++j)
    if (segment_begin(polyline, j) == segment_end(polyline, j))
      throw std::invalid_argument(where(name) + ": segment " + std::to_string(j) +
                                  " has length 0 (repeated vertex)");
  for (std::size_t i = 0; i < segments; ++i)
    for (std::size_t j = i + 1; j < segments; ++j) {
      const RationalPoint a = segment_begin(polyline, i), b = segment_end(polyline, i);
      const RationalPoint c = segment_begin(polyline, j), d = segment_end(polyline, j);
      const bool next = j == i + 1, wrap = polyline.closed && i == 0 && j == segments - 1;
      if (next || wrap) {
        // Adjacent segments share one vertex; they may not fold back over each other.
        const RationalPoint& before = next ? a : c;
        const RationalPoint& shared = next ? b : a;
        const RationalPoint& after = next ? d : b;
        const bool folds = orientation(before, shared, after) == 0 &&
                           (shared.x - before.x) * (after.x - shared.x) +
                                   (shared.y - before.y) * (after.y - shared.y) <
                               0;
        if (folds)
          throw std::invalid_argument(where(name) + ": segments " + std::to_string(i) + " and " +
                                      std::to_string(j) + " fold back over each other");
        continue;
      }
      if (segments_meet(a, b, c, d))
        throw std::invalid_argument(where(name) + " is not simple: segments " + std::to_string(i) +
                                    " and " + std::to_string(j) + " meet");
    }
}

bool components_meet(const Component& p, const Component& q) {
  if (const auto* circle = std::get_if<Circle>(&p)) {
    if (const auto* other = std::get_if<Circle>(&q))
      return circles_meet(*circle, *other);
    const auto& polyline = std::get<Polyline>(q);
    for (std::size_t j = 0; j < segment_count(polyline); ++j)
      if (segment_meets_circle(segment_begin(polyline, j), segment_end(polyline, j), *circle))
        return true;
    return false;
  }
  if (std::holds_alternative<Circle>(q))
    return components_meet(q, p);
  const auto& first = std::get<Polyline>(p);
  const auto& second = std::get<Polyline>(q);
  for (std::size_t i = 0; i < segment_count(first); ++i)
    for (std::size_t j = 0; j < segment_count(second); ++j)
      if (segments_meet(segment_begin(first, i), segment_end(first, i), segment_begin(second, j),
                        segment_end(second, j)))
        return true;
  return false;
}

} // namespace

Curve::Curve(std::vector<Component> components, std::string name)
    : components_(std::move(components)), name_(std::move(name)) {
  if (components_.empty())
    throw std::invalid_argument(where(name_) + " has no component");
  for (std::size_t c = 0; c < components_.size(); ++c) {
    if (const auto* circle = std::get_if<Circle>(&components_[c])) {
      if (circle->radius <= 0)
        throw std::invalid_argument(where(name_) + ": circle radius must be positive");
    } else {
      check_polyline(std::get<Polyline>(components_[c]), name_);
    }
    if (components_.size() > 1 && !closed(c))
      throw std::invalid_argument(where(name_) +
                                  ": a curve of several components needs every one closed");
  }
  for (std::size_t i = 0; i < components_.size(); ++i)
    for (std::size_t j = i + 1; j < components_.size(); ++j)
      if (components_meet(components_[i], components_[j]))
        throw std::invalid_argument(where(name_) + " is not simple: components " +
                                    std::to_string(i) + " and " + std::to_string(j) + " meet");

  segment_starts_.resize(components_.size());
  for (std::size_t c = 0; c < components_.size(); ++c) {
    if (const auto* circle = std::get_if<Circle>(&components_[c])) {
      lengths_.push_back(2 * boost::math::constants::pi<Real>() * Real(circle->radius));
      continue;
    }
    const auto& polyline = std::get<Polyline>(components_[c]);
    Real s = 0;
    for (std::size_t j = 0; j < segment_count(polyline); ++j) {
      segment_starts_[c].push_back(s);
      s += exact::segment_length(segment_begin(polyline, j), segment_end(polyline, j));
    }
    lengths_.push_back(s);
  }
}

Curve Curve::polyline(std::vector<RationalPoint> vertices, bool closed) {
  return Curve({Polyline{std::move(vertices), closed}});
}

Curve Curve::rectangle(const RationalPoint& corner, const RationalPoint& opposite) {
  const Rational left = std::min(corner.x, opposite.x), right = std::max(corner.x, opposite.x);
  const Rational top = std::min(corner.y, opposite.y), bottom = std::max(corner.y, opposite.y);
  return Curve({Polyline{{{left, top}, {right, top}, {right, bottom}, {left, bottom}}, true}});
}

Curve Curve::circle(const RationalPoint& centre, const Rational& radius) {
  return Curve({Circle{centre, radius}});
}

Curve Curve::annulus(const RationalPoint& centre, const Rational& inner, const Rational& outer) {
  if (!(inner < outer))
    throw std::invalid_argument("annulus: the inner radius must be less than the outer one");
  return Curve({Circle{centre, inner}, Circle{centre, outer}});
}

bool Curve::closed(std::size_t component) const {
  if (const auto* polyline = std::get_if<Polyline>(&components_[component]))
    return polyline->closed;
  return true;
}

Real Curve::length() const {
  Real total = 0;
  for (const Real& l : lengths_)
    total += l;
  return total;
}

Point Curve::point(std::size_t component, const Real& s_in) const {
  const Real& total = lengths_[component];
  const Real s = s_in < 0 ? Real(0) : (s_in > total ? total : s_in);
  if (const auto* circle = std::get_if<Circle>(&components_[component])) {
    const Real r(circle->radius);
    const Real angle = s / r;
    return {Real(circle->centre.x) + r * cos(angle), Real(circle->centre.y) + r * sin(angle)};
  }
  const auto& polyline = std::get<Polyline>(components_[component]);
  const auto& starts = segment_starts_[component];
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), s) -
                                                 starts.begin() - 1);
  const RationalPoint a = segment_begin(polyline, j), b = segment_end(polyline, j);
  const Real end = j + 1 < starts.size() ? starts[j + 1] : total;
  const Real t = (s - starts[j]) / (end - starts[j]);
  return {Real(a.x) + t * Real(b.x - a.x), Real(a.y) + t * Real(b.y - a.y)};
}

RationalPoint Curve::lower_corner() const {
  RationalPoint low;
  bool first = true;
  auto take = [&](const Rational& x, const Rational& y) {
    if (first || x < low.x)
      low.x = x;
    if (first || y < low.y)
      low.y = y;
    first = false;
  };
  for (const auto& component : components_) {
    if (const auto* circle = std::get_if<Circle>(&component))
      take(circle->centre.x - circle->radius, circle->centre.y - circle->radius);
    else
      for (const auto& v : std::get<Polyline>(component).vertices)
        take(v.x, v.y);
  }
  return low;
}

RationalPoint Curve::upper_corner() const {
  RationalPoint high;
  bool first = true;
  auto take = [&](const Rational& x, const Rational& y) {
    if (first || x > high.x)
      high.x = x;
    if (first || y > high.y)
      high.y = y;
    first = false;
  };
  for (const auto& component : components_) {
    if (const auto* circle = std::get_if<Circle>(&component))
      take(circle->centre.x + circle->radius, circle->centre.y + circle->radius);
    else
      for (const auto& v : std::get<Polyline>(component).vertices)
        take(v.x, v.y);
  }
  return high;
}

} // namespace mc
