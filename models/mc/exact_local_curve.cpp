#include "models/mc/exact_local_curve.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/mc/curve_numbers.hpp"

namespace mc {

namespace {

// "√2", "√(5/4)"
std::string format_root(const Rational& squared) {
  const std::string radicand = to_string(squared);
  return radicand.find('/') == std::string::npos ? "√" + radicand : "√(" + radicand + ")";
}

// The curve itself when every arc length is rational; else the refusal.
Curve exact_only(Curve curve) {
  const std::string prefix = "positions need exact arc lengths: ";
  const bool several = curve.component_count() > 1;
  for (std::size_t c = 0; c < curve.component_count(); ++c) {
    const std::string component = several ? "component " + std::to_string(c) + ", " : "";
    if (const auto* circle = std::get_if<Circle>(&curve.components()[c]))
      throw std::invalid_argument(prefix + "component " + std::to_string(c) +
                                  " is a circle (centre " + to_string(circle->centre) +
                                  ", radius " + to_string(circle->radius) +
                                  "), whose arcs have no rational length");
    const auto& polyline = std::get<Polyline>(curve.components()[c]);
    for (std::size_t j = 0; j < segment_count(polyline); ++j) {
      const RationalPoint a = segment_begin(polyline, j), e = segment_end(polyline, j);
      const Rational squared = (e.x - a.x) * (e.x - a.x) + (e.y - a.y) * (e.y - a.y);
      if (!exact::sqrt_if_square(squared))
        throw std::invalid_argument(prefix + component + "segment " + std::to_string(j) + " from " +
                                    to_string(a) + " to " + to_string(e) + " has length " +
                                    format_root(squared));
    }
  }
  return curve;
}

// One polyline component with its exact natural parameter.
struct ExactComponent {
  const Polyline* polyline;
  std::vector<Rational> starts;  // natural parameter where segment j begins
  std::vector<Rational> lengths; // of segment j
  std::vector<RationalPoint> directions;
  std::vector<Rational> cuts; // natural parameters of vertices and grid crossings
  Rational length;

  ExactComponent(const Polyline& line, int m, const Rational& b) : polyline(&line) {
    const std::size_t segments = segment_count(line);
    for (std::size_t j = 0; j < segments; ++j) {
      const RationalPoint a = segment_begin(line, j), e = segment_end(line, j);
      const Rational dx = e.x - a.x, dy = e.y - a.y;
      const Rational l = *exact::sqrt_if_square(dx * dx + dy * dy);
      starts.push_back(length);
      lengths.push_back(l);
      directions.push_back({dx / l, dy / l});
      cuts.push_back(length);
      for (int k = 1; k < m; ++k) {
        if (dx != 0)
          if (const Rational t = (k * b - a.x) / dx; t > 0 && t < 1)
            cuts.push_back(length + t * l);
        if (dy != 0)
          if (const Rational t = (k * b - a.y) / dy; t > 0 && t < 1)
            cuts.push_back(length + t * l);
      }
      length += l;
    }
    cuts.push_back(length);
    std::sort(cuts.begin(), cuts.end());
  }

  // The cut point whose natural parameter CurveOnGrid computed (in 100-digit floating
  // point) as `rounded`: the only one within 10^-60 of it.
  Rational snap(const Real& rounded) const {
    const Real tolerance = Real("1e-60") * (1 + abs(rounded));
    const Rational* found = nullptr;
    for (const Rational& cut : cuts)
      if (abs(Real(cut) - rounded) <= tolerance) {
        if (found && *found != cut)
          throw PrecisionError("two grid crossings of the curve lie within 1e-60 of each other");
        found = &cut;
      }
    if (!found)
      throw std::logic_error("exact_curve: a local part of the curve does not start at a vertex "
                             "or grid crossing");
    return *found;
  }

  // The segment on which natural parameter s (in [0, length]) lies, the earlier one at a
  // vertex except at the very end.
  std::size_t segment_at(const Rational& s) const {
    const auto it = std::upper_bound(starts.begin(), starts.end(), s);
    return static_cast<std::size_t>(it - starts.begin()) - 1;
  }

  RationalPoint at(std::size_t j, const Rational& s) const {
    const RationalPoint a = segment_begin(*polyline, j);
    const Rational along = s - starts[j];
    return {a.x + along * directions[j].x, a.y + along * directions[j].y};
  }
};

Rational wrap(const Rational& s, const Rational& period) {
  Rational w = s;
  while (w < 0)
    w += period;
  while (w >= period)
    w -= period;
  return w;
}

} // namespace

ExactCurve::ExactCurve(Curve curve, const GridTiling& tiling, const Rational& sigma,
                       const Rational& b)
    : grid_(tiling), on_grid_(exact_only(std::move(curve)), tiling, sigma, b) {
  const Curve& gamma = on_grid_.curve();
  std::vector<ExactComponent> components;
  std::vector<Rational> offsets, origins;
  Rational offset = 0;
  for (std::size_t c = 0; c < gamma.component_count(); ++c) {
    components.emplace_back(std::get<Polyline>(gamma.components()[c]), on_grid_.m(), b);
    offsets.push_back(offset);
    origins.push_back(gamma.closed(c) ? components.back().snap(on_grid_.origin(c)) : Rational(0));
    offset += components.back().length;
  }

  local_.resize(on_grid_.size());
  for (RegionId u = 0; u < local_.size(); ++u) {
    const LocalPart& rounded = on_grid_.local(u);
    ExactLocalPart& part = local_[u];
    part.region = u;
    if (rounded.empty)
      continue;
    part.empty = false;
    part.component = rounded.component;
    part.inf_owned = rounded.inf_owned;
    part.sup_owned = rounded.sup_owned;
    part.q = rounded.q;
    part.length = rounded.length.rational(); // exact: every segment has a rational length
    const std::size_t c = part.component;
    const ExactComponent& line = components[c];
    const bool closed = gamma.closed(c);
    const Rational begin = line.snap(rounded.natural_begin);
    part.inf = offsets[c] + (closed ? wrap(begin - origins[c], line.length) : begin);
    if (abs(Real(part.inf) - rounded.inf) > Real("1e-60") * (1 + abs(rounded.inf)))
      throw std::logic_error("exact_curve: inf P_u of " + describe_region(u, on_grid_.m()) +
                             " disagrees with CurveOnGrid");

    // Walk from the natural parameter `begin` along |A_u|, segment by segment (around
    // the end of a closed component).
    Rational s = 0, natural = begin;
    std::size_t j = line.segment_at(begin);
    const std::size_t segments = line.starts.size();
    for (;;) {
      const Rational take =
          std::min<Rational>(line.starts[j] + line.lengths[j] - natural, part.length - s);
      part.pieces.push_back({j, s, s + take, line.at(j, natural), line.directions[j]});
      s += take;
      if (s == part.length)
        break;
      j = (j + 1) % segments;
      natural = line.starts[j];
    }
  }
}

RationalPoint ExactCurve::point(RegionId u, const Rational& s) const {
  const ExactLocalPart& part = local(u);
  if (part.empty)
    throw std::invalid_argument("the curve does not meet " + describe_region(u, grid_.m()));
  if (s < 0 || s > part.length)
    throw std::out_of_range("parameter " + to_string(s) + " outside [0, " + to_string(part.length) +
                            "] of " + describe_region(u, grid_.m()));
  for (const ExactPiece& piece : part.pieces)
    if (s <= piece.end) {
      const Rational along = s - piece.begin;
      return {piece.start.x + along * piece.direction.x, piece.start.y + along * piece.direction.y};
    }
  throw std::logic_error("exact_curve: pieces do not cover [0, |A_u|]");
}

ExactNearest ExactCurve::nearest(RegionId u, const RationalPoint& x) const {
  const ExactLocalPart& part = local(u);
  if (part.empty)
    throw std::invalid_argument("the curve does not meet " + describe_region(u, grid_.m()));
  std::optional<ExactNearest> best;
  for (const ExactPiece& piece : part.pieces) {
    // The projection onto the piece's line, clamped into the piece.
    Rational along =
        (x.x - piece.start.x) * piece.direction.x + (x.y - piece.start.y) * piece.direction.y;
    const Rational span = piece.end - piece.begin;
    if (along < 0)
      along = 0;
    else if (along > span)
      along = span;
    const RationalPoint y{piece.start.x + along * piece.direction.x,
                          piece.start.y + along * piece.direction.y};
    const Rational squared = (x.x - y.x) * (x.x - y.x) + (x.y - y.y) * (x.y - y.y);
    const Rational parameter = piece.begin + along;
    if (!best || squared < best->squared_distance ||
        (squared == best->squared_distance && parameter < best->parameter))
      best = ExactNearest{parameter, y, squared};
  }
  return *best;
}

std::optional<Rational> ExactCurve::parameter(RegionId u, const RationalPoint& x) const {
  ExactNearest found = nearest(u, x);
  if (found.squared_distance != 0)
    return std::nullopt;
  return std::move(found.parameter);
}

bool ExactCurve::in_closure(RegionId u, const RationalPoint& x) const {
  const Region r = grid_.region(u);
  const Rational& b = on_grid_.b();
  return x.x >= r.col * b && x.x <= (r.col + 1) * b && x.y >= r.row * b && x.y <= (r.row + 1) * b;
}

} // namespace mc
