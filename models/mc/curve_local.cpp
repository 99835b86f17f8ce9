#include "models/mc/curve_local.hpp"

#include <algorithm>
#include <sstream>

#include <boost/math/constants/constants.hpp>

#include "models/mc/curve_numbers.hpp"

namespace mc {

const Real& certification_margin() {
  static const Real margin("1e-70");
  return margin;
}

std::string describe_region(RegionId u, int m) {
  return "region " + std::to_string(u) + " (row " + std::to_string(static_cast<int>(u) / m) +
         ", col " + std::to_string(static_cast<int>(u) % m) + ")";
}

// ---------------------------------------------------------------------------- ArcLength

void ArcLength::add_segment_piece(const Rational& fraction, const Rational& squared) {
  if (const auto root = exact::sqrt_if_square(squared))
    rational_ += fraction * *root;
  else
    surds_[squared] += fraction;
}

void ArcLength::add_arc(const Rational& radius, const Real& angle) {
  arcs_ += Real(radius) * angle;
  ++arc_count_;
}

void ArcLength::add(const ArcLength& other) {
  rational_ += other.rational_;
  for (const auto& [radicand, coefficient] : other.surds_)
    surds_[radicand] += coefficient;
  arcs_ += other.arcs_;
  arc_count_ += other.arc_count_;
}

Real ArcLength::value() const {
  Real total = Real(rational_) + arcs_;
  for (const auto& [radicand, coefficient] : surds_)
    total += Real(coefficient) * sqrt(Real(radicand));
  return total;
}

std::int64_t ArcLength::quanta(const Rational& sigma, const std::string& what) const {
  constexpr std::int64_t limit = std::int64_t{1} << 62;
  exact::Integer ceiling;
  if (exact()) {
    ceiling = -floor_of(-(rational_ / sigma));
  } else {
    // Irrational (see the header): never an integer, so only the rounding can fail us.
    const Real v = value() / Real(sigma);
    const Real below = floor(v);
    const Real fraction = v - below;
    const Real margin = certification_margin() * (1 + abs(v));
    if (fraction < margin || 1 - fraction < margin)
      throw PrecisionError(what + ": |A_u|/σ = " + v.str(30) + "… lies within 1e-70 of an " +
                           "integer; 100-digit arithmetic cannot decide its ceiling");
    ceiling = below.convert_to<exact::Integer>() + 1;
  }
  if (ceiling >= limit)
    throw std::invalid_argument(what + ": |A_u|/σ is too large (σ too small)");
  return ceiling.convert_to<std::int64_t>();
}

std::string ArcLength::to_string() const {
  if (exact())
    return rational_.str();
  return value().str(25) + "…";
}

// ------------------------------------------------------------------------ the pieces

namespace {

using exact::QuadraticIrrational;

// A piece of one component in its natural parameter: a single point (owned by `region`),
// or the open stretch strictly between two such points, inside one region.
struct Atom {
  RegionId region;
  bool point;
  Real s_begin, s_end;
  ArcLength length;
};

class Cells {
public:
  Cells(int m, const Rational& b) : m_(m), b_(b), real_b_(b) {}

  int clamp(const exact::Integer& k) const {
    if (k < 0)
      return 0;
    if (k >= m_)
      return m_ - 1;
    return k.convert_to<int>();
  }
  RegionId id(int row, int col) const { return static_cast<RegionId>(row * m_ + col); }

  RegionId owner(const RationalPoint& p) const {
    return id(clamp(floor_of(p.y / b_)), clamp(floor_of(p.x / b_)));
  }
  RegionId owner(const QuadraticIrrational& x, const QuadraticIrrational& y) const {
    return id(clamp(exact::floor_div(y, b_)), clamp(exact::floor_div(x, b_)));
  }
  // The region of a point known to lie off every interior grid line, certified.
  RegionId certified_owner(const Point& p) const {
    return id(certified_cell(p.y), certified_cell(p.x));
  }
  RegionId rounded_owner(const Point& p) const {
    return id(clamp(exact::Integer(floor(p.y / real_b_).convert_to<exact::Integer>())),
              clamp(exact::Integer(floor(p.x / real_b_).convert_to<exact::Integer>())));
  }

private:
  int m_;
  Rational b_;
  Real real_b_;

  int certified_cell(const Real& coordinate) const {
    const Real v = coordinate / real_b_;
    const Real below = floor(v);
    const Real margin = certification_margin() * (1 + abs(v));
    const exact::Integer k = below.convert_to<exact::Integer>();
    if ((k >= 1 && k <= m_ - 1 && v - below < margin) ||
        (k + 1 >= 1 && k + 1 <= m_ - 1 && below + 1 - v < margin))
      throw PrecisionError("a circle arc passes within 1e-70 of a grid line; 100-digit "
                           "arithmetic cannot decide which region it lies in");
    return clamp(k);
  }
};

// The atoms of a polyline component in natural order: each vertex, each crossing of an
// interior grid line, and the open stretches between them. All crossings are at rational
// fractions t of their segment, so owners are decided exactly.
std::vector<Atom> polyline_atoms(const Curve& curve, std::size_t c, const Cells& cells, int m,
                                 const Rational& b) {
  const auto& polyline = std::get<Polyline>(curve.components()[c]);
  const std::size_t segments = segment_count(polyline);
  std::vector<Atom> atoms;
  for (std::size_t j = 0; j < segments; ++j) {
    const RationalPoint a = segment_begin(polyline, j), e = segment_end(polyline, j);
    const Rational dx = e.x - a.x, dy = e.y - a.y;
    const Rational squared = dx * dx + dy * dy;
    const Real start = curve.segment_start(c, j);
    const Real length = exact::segment_length(a, e);
    std::vector<Rational> ts{Rational(0), Rational(1)};
    for (int k = 1; k < m; ++k) {
      if (dx != 0) {
        const Rational t = (k * b - a.x) / dx;
        if (t > 0 && t < 1)
          ts.push_back(t);
      }
      if (dy != 0) {
        const Rational t = (k * b - a.y) / dy;
        if (t > 0 && t < 1)
          ts.push_back(t);
      }
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    auto at = [&](const Rational& t) { return RationalPoint{a.x + t * dx, a.y + t * dy}; };
    auto s_of = [&](const Rational& t) { return start + Real(t) * length; };
    const bool last_of_open = !polyline.closed && j + 1 == segments;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      if (i + 1 < ts.size() || last_of_open)
        atoms.push_back({cells.owner(at(ts[i])), true, s_of(ts[i]), s_of(ts[i]), ArcLength{}});
      if (i + 1 < ts.size()) {
        ArcLength piece;
        piece.add_segment_piece(ts[i + 1] - ts[i], squared);
        const Rational middle = (ts[i] + ts[i + 1]) / 2;
        atoms.push_back({cells.owner(at(middle)), false, s_of(ts[i]), s_of(ts[i + 1]), piece});
      }
    }
  }
  return atoms;
}

// A point where a circle meets an interior grid line: exact coordinates, rounded angle.
struct CircleEvent {
  QuadraticIrrational x, y;
  Real angle; // in [0, 2π), from the +x direction towards +y
};

// The atoms of a circle in natural order, starting at its first grid crossing (natural
// parameters may run past 2πr; they are taken modulo the length where it matters).
std::vector<Atom> circle_atoms(const Circle& circle, const Cells& cells, int m, const Rational& b) {
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  const Rational& cx = circle.centre.x;
  const Rational& cy = circle.centre.y;
  const Rational& r = circle.radius;
  const Real real_r(r);
  std::vector<CircleEvent> events;
  auto add = [&](const QuadraticIrrational& x, const QuadraticIrrational& y) {
    Real angle = atan2(y.value() - Real(cy), x.value() - Real(cx));
    if (angle < 0)
      angle += two_pi;
    events.push_back({x, y, angle});
  };
  for (int k = 1; k < m; ++k) {
    const Rational line = k * b;
    const Rational vertical = r * r - (line - cx) * (line - cx); // meets x = line
    if (vertical >= 0) {
      for (int sign : vertical == 0 ? std::vector<int>{0} : std::vector<int>{-1, 1})
        add(QuadraticIrrational::make(line, 0, 0), QuadraticIrrational::make(cy, sign, vertical));
    }
    const Rational horizontal = r * r - (line - cy) * (line - cy); // meets y = line
    if (horizontal >= 0) {
      for (int sign : horizontal == 0 ? std::vector<int>{0} : std::vector<int>{-1, 1})
        add(QuadraticIrrational::make(cx, sign, horizontal), QuadraticIrrational::make(line, 0, 0));
    }
  }
  std::vector<Atom> atoms;
  if (events.empty()) { // inside one region
    ArcLength whole;
    whole.add_arc(r, two_pi);
    atoms.push_back({cells.owner(RationalPoint{cx + r, cy}), false, 0, two_pi * real_r, whole});
    return atoms;
  }
  std::sort(events.begin(), events.end(),
            [](const CircleEvent& p, const CircleEvent& q) { return p.angle < q.angle; });
  // A grid vertex on the circle is found twice (once per line): merge exact duplicates.
  // Distinct points closer than the margin cannot be ordered with certainty.
  std::vector<CircleEvent> distinct;
  for (const auto& event : events) {
    if (!distinct.empty() && event.angle - distinct.back().angle < certification_margin()) {
      if (event.x == distinct.back().x && event.y == distinct.back().y)
        continue;
      throw PrecisionError("two points where a circle meets grid lines lie within 1e-70 of "
                           "each other; 100-digit arithmetic cannot order them");
    }
    distinct.push_back(event);
  }
  if (distinct.size() > 1 &&
      distinct.front().angle + two_pi - distinct.back().angle < certification_margin()) {
    if (!(distinct.front().x == distinct.back().x && distinct.front().y == distinct.back().y))
      throw PrecisionError("two points where a circle meets grid lines lie within 1e-70 of "
                           "each other; 100-digit arithmetic cannot order them");
    distinct.pop_back();
  }
  const Real real_cx(cx), real_cy(cy);
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const Real from = distinct[i].angle;
    const Real to = i + 1 < distinct.size() ? distinct[i + 1].angle : distinct[0].angle + two_pi;
    atoms.push_back({cells.owner(distinct[i].x, distinct[i].y), true, real_r * from, real_r * from,
                     ArcLength{}});
    const Real middle = (from + to) / 2;
    const Point inside{real_cx + real_r * cos(middle), real_cy + real_r * sin(middle)};
    ArcLength arc;
    arc.add_arc(r, to - from);
    atoms.push_back({cells.certified_owner(inside), false, real_r * from, real_r * to, arc});
  }
  return atoms;
}

Real wrap(const Real& x, const Real& period) {
  Real y = x;
  while (y < 0)
    y += period;
  while (y >= period)
    y -= period;
  return y;
}

} // namespace

// ---------------------------------------------------------------------- CurveOnGrid

CurveOnGrid::CurveOnGrid(Curve curve, const GridTiling& tiling, const Rational& sigma,
                         const Rational& b)
    : curve_(std::move(curve)), m_(tiling.m()), b_(b), sigma_(sigma) {
  if (sigma_ <= 0)
    throw std::invalid_argument("quantisation constant sigma must be positive, not " +
                                sigma_.str());
  if (b_ <= 0)
    throw std::invalid_argument("region side b must be positive, not " + b_.str());
  const Rational side = m_ * b_;
  const RationalPoint low = curve_.lower_corner(), high = curve_.upper_corner();
  if (low.x < 0 || low.y < 0 || high.x > side || high.y > side)
    throw std::invalid_argument(
        (curve_.name().empty() ? std::string("curve") : "curve " + curve_.name()) +
        " leaves the deployment square [0, " + side.str() + "]^2");

  const Cells cells(m_, b_);
  const std::size_t n = tiling.size();
  local_.resize(n);
  for (RegionId u = 0; u < n; ++u)
    local_[u].region = u;

  Real offset = 0;
  for (std::size_t c = 0; c < curve_.component_count(); ++c) {
    std::vector<Atom> atoms =
        std::holds_alternative<Circle>(curve_.components()[c])
            ? circle_atoms(std::get<Circle>(curve_.components()[c]), cells, m_, b_)
            : polyline_atoms(curve_, c, cells, m_, b_);
    const Real& period = curve_.length(c);
    const bool closed = curve_.closed(c);
    const bool one_region = std::all_of(atoms.begin(), atoms.end(), [&](const Atom& atom) {
      return atom.region == atoms.front().region;
    });

    // Origin of a closed component: the first point atom that begins a new region.
    std::size_t first = 0;
    if (closed && !one_region) {
      const std::size_t count = atoms.size();
      first = count;
      for (std::size_t i = 0; i < count && first == count; ++i)
        if (atoms[i].point && atoms[(i + count - 1) % count].region != atoms[i].region)
          first = i;
      if (first == count) // cannot happen: Γ enters a closed set at a point it owns
        throw std::logic_error("closed curve component without a region entry point");
      std::rotate(atoms.begin(), atoms.begin() + static_cast<std::ptrdiff_t>(first), atoms.end());
    }
    const Real origin = closed ? wrap(atoms.front().s_begin, period) : Real(0);
    offsets_.push_back(offset);
    origins_.push_back(origin);

    // Runs of atoms in one region become the local parts.
    for (std::size_t i = 0; i < atoms.size();) {
      std::size_t j = i;
      while (j < atoms.size() && atoms[j].region == atoms[i].region)
        ++j;
      const RegionId u = atoms[i].region;
      LocalPart& part = local_[u];
      if (!part.empty) {
        const std::string curve_name =
            curve_.name().empty() ? std::string("curve") : "curve " + curve_.name();
        const std::string how =
            part.component == c ? " enters " + describe_region(u, m_) + " more than once"
                                : " meets " + describe_region(u, m_) + " with components " +
                                      std::to_string(part.component) + " and " + std::to_string(c);
        throw std::invalid_argument(curve_name + how +
                                    ": A_u is not an interval (seed 000 §5.1 assumes A_u convex)");
      }
      part.empty = false;
      part.component = c;
      part.natural_begin = wrap(atoms[i].s_begin, period);
      part.inf = offset + (closed ? wrap(atoms[i].s_begin - origin, period) : atoms[i].s_begin);
      part.sup = part.inf;
      for (std::size_t k = i; k < j; ++k) {
        part.sup += atoms[k].s_end - atoms[k].s_begin;
        part.length.add(atoms[k].length);
      }
      part.inf_owned = atoms[i].point || (closed && one_region);
      part.sup_owned = atoms[j - 1].point || (closed && one_region);
      i = j;
    }
    offset += period;
  }

  q_.assign(n, 0);
  for (RegionId u = 0; u < n; ++u) {
    if (local_[u].empty)
      continue;
    local_[u].q = local_[u].length.quanta(sigma_, "quantised length of " + describe_region(u, m_));
    q_[u] = local_[u].q;
  }
  for (RegionId u = 0; u < n; ++u) {
    if (q_[u] == 0) {
      out_.push_back(u);
      continue;
    }
    in_.push_back(u);
    q_min_ = q_min_ == 0 ? q_[u] : std::min(q_min_, q_[u]);
    q_max_ = std::max(q_max_, q_[u]);
  }
}

std::vector<std::vector<std::int64_t>> CurveOnGrid::q_matrix() const {
  std::vector<std::vector<std::int64_t>> rows(static_cast<std::size_t>(m_));
  for (RegionId u = 0; u < q_.size(); ++u)
    rows[u / static_cast<RegionId>(m_)].push_back(q_[u]);
  return rows;
}

std::string CurveOnGrid::format_q() const {
  std::size_t width = 1;
  for (std::int64_t q : q_)
    width = std::max(width, std::to_string(q).size());
  std::ostringstream out;
  for (const auto& row : q_matrix()) {
    for (std::size_t col = 0; col < row.size(); ++col) {
      const std::string cell = row[col] == 0 ? "." : std::to_string(row[col]);
      out << (col ? " " : "") << std::string(width - cell.size(), ' ') << cell;
    }
    out << '\n';
  }
  return out.str();
}

Real CurveOnGrid::natural(std::size_t component, const Real& relative) const {
  if (!curve_.closed(component))
    return relative;
  return wrap(relative + origins_[component], curve_.length(component));
}

std::size_t CurveOnGrid::component_at(const Real& p) const {
  const auto it = std::upper_bound(offsets_.begin(), offsets_.end(), p);
  return static_cast<std::size_t>(it - offsets_.begin()) - 1;
}

Point CurveOnGrid::point(const Real& p) const {
  const Real total = length();
  const bool open = !curve_.closed(0);
  if (p < 0 || p > total || (!open && p == total))
    throw std::out_of_range("parameter " + p.str(20) + " outside the domain of the curve [0, " +
                            total.str(20) + (open ? "]" : ")"));
  const std::size_t c = component_at(p);
  return curve_.point(c, natural(c, p - offsets_[c]));
}

Point CurveOnGrid::point(RegionId u, const Real& p) const {
  const LocalPart& part = local(u);
  if (part.empty)
    throw std::invalid_argument("the curve does not meet " + describe_region(u, m_));
  const Real margin = certification_margin() * (1 + abs(part.sup));
  if (p < part.inf - margin || p > part.sup + margin)
    throw std::out_of_range("parameter " + p.str(20) + " outside P_u = [" + part.inf.str(20) +
                            ", " + part.sup.str(20) + "] of " + describe_region(u, m_));
  const Real clamped = p < part.inf ? part.inf : (p > part.sup ? part.sup : p);
  return curve_.point(part.component, natural(part.component, clamped - offsets_[part.component]));
}

NearestPoint CurveOnGrid::nearest(RegionId u, const Point& x) const {
  const LocalPart& part = local(u);
  if (part.empty)
    throw std::invalid_argument("the curve does not meet " + describe_region(u, m_));
  const std::size_t c = part.component;
  const Real& period = curve_.length(c);
  // The run in "unwrapped" natural parameters [from, to]; `to` may pass the period.
  const Real from = part.natural_begin;
  const Real to = from + (part.sup - part.inf);

  std::optional<NearestPoint> best;
  auto consider = [&](const Real& unwrapped) {
    const Real p = part.inf + (unwrapped - from);
    const Point y = curve_.point(c, wrap(unwrapped, period));
    const Real d = distance(x, y);
    const Real margin = certification_margin() * (1 + d);
    if (!best || d < best->distance - margin ||
        (d <= best->distance + margin && p < best->parameter))
      best = NearestPoint{p, y, d};
  };

  if (const auto* circle = std::get_if<Circle>(&curve_.components()[c])) {
    const Point centre = to_point(circle->centre);
    const Real r(circle->radius);
    if (distance(x, centre) <= certification_margin() * (1 + r)) {
      consider(from); // every point is nearest: the smallest parameter
    } else {
      const Real two_pi = 2 * boost::math::constants::pi<Real>();
      const Real s = r * wrap(atan2(x.y - centre.y, x.x - centre.x), two_pi);
      bool inside = false;
      for (int k = -1; k <= 2; ++k) {
        const Real candidate = s + k * period;
        if (candidate >= from && candidate <= to) {
          consider(candidate);
          inside = true;
        }
      }
      if (!inside) { // the nearest point of the arc is one of its ends
        consider(from);
        consider(to);
      }
    }
  } else {
    const auto& polyline = std::get<Polyline>(curve_.components()[c]);
    const std::size_t segments = segment_count(polyline);
    for (int shift = 0; shift <= (curve_.closed(c) ? 1 : 0); ++shift)
      for (std::size_t j = 0; j < segments; ++j) {
        const Real start = curve_.segment_start(c, j) + shift * period;
        const Real end =
            (j + 1 < segments ? curve_.segment_start(c, j + 1) : period) + shift * period;
        const Real lo = std::max(start, from), hi = std::min(end, to);
        if (lo > hi)
          continue;
        const Point a = to_point(segment_begin(polyline, j));
        const Point e = to_point(segment_end(polyline, j));
        const Real dx = e.x - a.x, dy = e.y - a.y;
        const Real t = ((x.x - a.x) * dx + (x.y - a.y) * dy) / (dx * dx + dy * dy);
        Real s = start + t * (end - start);
        s = s < lo ? lo : (s > hi ? hi : s);
        consider(s);
      }
  }
  return *best;
}

std::optional<Real> CurveOnGrid::parameter(RegionId u, const Point& x,
                                           const Real& tolerance) const {
  const NearestPoint nearest_point = nearest(u, x);
  if (nearest_point.distance > tolerance)
    return std::nullopt;
  return nearest_point.parameter;
}

RegionId CurveOnGrid::region_of(const RationalPoint& x) const {
  return Cells(m_, b_).owner(x);
}

RegionId CurveOnGrid::region_of(const Point& x) const {
  return Cells(m_, b_).rounded_owner(x);
}

RationalPoint CurveOnGrid::centre(RegionId u) const {
  const int row = static_cast<int>(u) / m_, col = static_cast<int>(u) % m_;
  return {(col + Rational(1, 2)) * b_, (row + Rational(1, 2)) * b_};
}

} // namespace mc
