#include "proofs/random_curve.hpp"

#include <array>
#include <cmath>
#include <set>
#include <utility>

#include "models/mc/curve_numbers.hpp"
#include "models/mc/grid.hpp"

namespace proofs {

namespace {

using mc::Rational;
using mc::RationalPoint;

struct Cell {
  int row = 0, col = 0;
};

// A lattice point strictly inside the region: (col + i/8, row + j/8), i, j in 1..7.
RationalPoint inside(const Cell& cell, SplitMix64& random) {
  const auto eighth = [&] { return Rational(static_cast<long>(1 + random.below(7)), 8); };
  const Rational x = Rational(cell.col) + eighth();
  const Rational y = Rational(cell.row) + eighth();
  return {x, y};
}

// The point where the path goes from `from` to its neighbour `to`: strictly inside their
// shared side, or their shared vertex for a diagonal step.
RationalPoint crossing(const Cell& from, const Cell& to, SplitMix64& random) {
  const int drow = to.row - from.row, dcol = to.col - from.col;
  const Rational along(static_cast<long>(1 + random.below(7)), 8);
  if (drow == 0) // a vertical side at x = max(col)
    return {Rational(std::max(from.col, to.col)), Rational(from.row) + along};
  if (dcol == 0) // a horizontal side at y = max(row)
    return {Rational(from.col) + along, Rational(std::max(from.row, to.row))};
  return {Rational(std::max(from.col, to.col)), Rational(std::max(from.row, to.row))};
}

// The piece of the path in each region, as the points it runs through: P_0 to X_0, X_(i−1)
// to X_i through region r_i, X_(L−1) to P_L (a one-region path: its two points). Straight:
// through the region's inner point P_i.
std::vector<std::vector<RationalPoint>>
straight_pieces(const std::vector<RationalPoint>& interior,
                const std::vector<RationalPoint>& crossings) {
  if (crossings.empty())
    return {{interior[0], interior[1]}};
  std::vector<std::vector<RationalPoint>> out{{interior[0], crossings[0]}};
  for (std::size_t i = 1; i < crossings.size(); ++i)
    out.push_back({crossings[i - 1], interior[i], crossings[i]});
  out.push_back({crossings.back(), interior.back()});
  return out;
}

bool whole(const Rational& r) {
  return denominator(r) == 1;
}

// From a to b inside one region with axis-parallel segments, so that every length is
// rational (positions need exact arc lengths). A point on a vertical side is left or
// reached horizontally, one on a horizontal side vertically, an inner point either way;
// `inner` (a point strictly inside) places the middle leg when a and b lie on opposite
// sides. Every corner is strictly inside the region (one coordinate of an inner lattice
// point or a side's inner point each), so the route meets no other region.
void route(std::vector<RationalPoint>& out, const RationalPoint& a, const RationalPoint& b,
           const RationalPoint& inner) {
  const auto add = [&out](const RationalPoint& p) {
    if (out.empty() || !(out.back() == p))
      out.push_back(p);
  };
  add(a);
  if (a.x != b.x && a.y != b.y) {
    const bool a_horizontal = whole(a.x), b_horizontal = whole(b.x); // on a vertical side
    const bool a_vertical = whole(a.y), b_vertical = whole(b.y);     // on a horizontal side
    if (a_horizontal && b_horizontal) {
      add({inner.x, a.y});
      add({inner.x, b.y});
    } else if (a_vertical && b_vertical) {
      add({a.x, inner.y});
      add({b.x, inner.y});
    } else if (a_horizontal || b_vertical) {
      add({b.x, a.y});
    } else {
      add({a.x, b.y});
    }
  }
  add(b);
}

// The same pieces with legs parallel to the axes (route), each region's P_i placing its
// middle leg.
std::vector<std::vector<RationalPoint>>
axis_parallel_pieces(const std::vector<RationalPoint>& interior,
                     const std::vector<RationalPoint>& crossings) {
  std::vector<std::vector<RationalPoint>> out(std::max<std::size_t>(1, crossings.size() + 1));
  if (crossings.empty()) {
    route(out[0], interior[0], interior[1], interior[0]);
    return out;
  }
  route(out[0], interior[0], crossings[0], interior[0]);
  for (std::size_t i = 1; i < crossings.size(); ++i)
    route(out[i], crossings[i - 1], crossings[i], interior[i]);
  route(out.back(), crossings.back(), interior.back(), interior.back());
  return out;
}

// Whether r + √a + √b ≤ c, exactly (r, a, b >= 0 rational): squaring twice, as every term
// compared is then rational.
bool at_most(const Rational& r, const Rational& a, const Rational& b, const Rational& c) {
  const Rational d = c - r; // √a + √b ≤ d
  if (d < 0)
    return false;
  const Rational e = d * d - a - b; // 2√(ab) ≤ e
  return e >= 0 && 4 * a * b <= e * e;
}

// ⌈|piece| / σ⌉ exactly. A piece has at most two segments of irrational length (a straight
// piece has two segments; the legs of an axis-parallel one are rational).
mc::QuantisedLength quanta(const std::vector<RationalPoint>& piece, const Rational& sigma) {
  Rational r = 0;
  std::vector<Rational> surds;
  double estimate = 0;
  for (std::size_t j = 1; j < piece.size(); ++j) {
    const Rational dx = piece[j].x - piece[j - 1].x, dy = piece[j].y - piece[j - 1].y;
    const Rational squared = dx * dx + dy * dy;
    estimate += std::sqrt(static_cast<double>(squared));
    if (const auto root = mc::exact::sqrt_if_square(squared))
      r += *root;
    else
      surds.push_back(squared);
  }
  if (surds.size() > 2)
    throw std::logic_error("random_grid_path: a piece with more than two oblique segments");
  surds.resize(2, Rational(0));
  // The smallest n with length ≤ n·σ, from the estimate.
  auto n = static_cast<mc::QuantisedLength>(std::ceil(estimate / static_cast<double>(sigma)));
  while (!at_most(r, surds[0], surds[1], n * sigma))
    ++n;
  while (n > 0 && at_most(r, surds[0], surds[1], (n - 1) * sigma))
    --n;
  return n;
}

} // namespace

mc::Curve GridPathCurve::curve() const {
  return mc::Curve::polyline(vertices);
}

std::string GridPathCurve::describe() const {
  std::string out = "a grid path through " + std::to_string(path.size()) + " region" +
                    (path.size() == 1 ? "" : "s");
  std::vector<std::string> notes;
  if (vertex_steps > 0)
    notes.push_back(std::to_string(vertex_steps) + " step" + (vertex_steps == 1 ? "" : "s") +
                    " through a vertex");
  if (rows_reentered > 0)
    notes.push_back("re-enters " + std::to_string(rows_reentered) + " row" +
                    (rows_reentered == 1 ? "" : "s"));
  if (!notes.empty()) {
    out += " (";
    for (std::size_t i = 0; i < notes.size(); ++i)
      out += (i ? ", " : "") + notes[i];
    out += ")";
  }
  return out + ", sigma = " + mc::to_string(sigma);
}

GridPathCurve random_grid_path(int m, SplitMix64& random, GridPathShape shape_of_path) {
  if (m < 1)
    throw std::invalid_argument("random_grid_path: m must be >= 1, not " + std::to_string(m));
  const auto regions = static_cast<std::uint64_t>(m) * static_cast<std::uint64_t>(m);
  const std::uint64_t shape = random.below(3);
  const std::uint64_t length = shape == 0 ? 1 + random.below(static_cast<std::uint64_t>(m))
                               : shape == 1
                                   ? 1 + random.below(std::max<std::uint64_t>(1, regions / 2))
                                   : regions;
  const auto id = [m](const Cell& c) { return static_cast<mc::RegionId>(c.row * m + c.col); };
  const auto on_grid = [m](const Cell& c) {
    return c.row >= 0 && c.row < m && c.col >= 0 && c.col < m;
  };

  std::vector<bool> taken(static_cast<std::size_t>(regions), false); // visited or touched
  std::set<std::pair<int, int>> vertices_used;                       // (x, y) of grid vertices
  std::vector<Cell> cells{{static_cast<int>(random.below(static_cast<std::uint64_t>(m))),
                           static_cast<int>(random.below(static_cast<std::uint64_t>(m)))}};
  taken[id(cells[0])] = true;
  GridPathCurve out;
  std::vector<RationalPoint> interior{inside(cells[0], random)}; // P_i of region r_i
  std::vector<RationalPoint> crossings;                          // X_i between r_i and r_(i+1)

  static constexpr std::array<std::pair<int, int>, 8> steps{
      {{0, 1}, {1, 0}, {0, -1}, {-1, 0}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
  while (cells.size() < length) {
    const Cell here = cells.back();
    std::vector<std::pair<Cell, int>> moves; // the next cell, and the third region a diagonal
                                             // step's vertex belongs to (-1: none)
    for (const auto& [drow, dcol] : steps) {
      const Cell next{here.row + drow, here.col + dcol};
      if (!on_grid(next) || taken[id(next)])
        continue;
      if (drow == 0 || dcol == 0) {
        moves.emplace_back(next, -1);
        continue;
      }
      if (shape_of_path.axis_parallel)
        continue; // a diagonal step needs a diagonal segment
      const int vx = std::max(here.col, next.col), vy = std::max(here.row, next.row);
      if (vertices_used.count({vx, vy}))
        continue;
      // The vertex belongs to the region south-east of it (curve_local.hpp).
      const Cell owner{vy, vx};
      const bool third = !(owner.row == here.row && owner.col == here.col) &&
                         !(owner.row == next.row && owner.col == next.col);
      if (third && on_grid(owner) && taken[id(owner)])
        continue; // the curve would meet that region a second time
      moves.emplace_back(next, third && on_grid(owner) ? static_cast<int>(id(owner)) : -1);
    }
    if (moves.empty())
      break;
    const auto& [next, touched] = moves[random.below(moves.size())];
    crossings.push_back(crossing(here, next, random));
    if (next.row != here.row && next.col != here.col) {
      ++out.vertex_steps;
      vertices_used.insert({std::max(here.col, next.col), std::max(here.row, next.row)});
    }
    if (touched >= 0)
      taken[static_cast<std::size_t>(touched)] = true;
    taken[id(next)] = true;
    cells.push_back(next);
    interior.push_back(inside(next, random));
  }
  if (cells.size() == 1) { // a curve inside one region: a second point there
    RationalPoint end = inside(cells[0], random);
    while (end == interior[0])
      end = inside(cells[0], random);
    interior.push_back(end);
  }
  const std::vector<std::vector<RationalPoint>> pieces =
      shape_of_path.axis_parallel ? axis_parallel_pieces(interior, crossings)
                                  : straight_pieces(interior, crossings);
  for (const auto& piece : pieces)
    for (const RationalPoint& p : piece)
      if (out.vertices.empty() || !(out.vertices.back() == p))
        out.vertices.push_back(p);

  // Rows left and entered again: a row whose regions on the path are not consecutive.
  std::vector<int> last_seen(static_cast<std::size_t>(m), -1);
  std::vector<bool> counted(static_cast<std::size_t>(m), false);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    auto& last = last_seen[static_cast<std::size_t>(cells[i].row)];
    if (last >= 0 && static_cast<std::size_t>(last) + 1 != i &&
        !counted[static_cast<std::size_t>(cells[i].row)]) {
      counted[static_cast<std::size_t>(cells[i].row)] = true;
      ++out.rows_reentered;
    }
    last = static_cast<int>(i);
  }

  static const std::array<Rational, 5> sigmas{Rational(1), Rational(1, 2), Rational(1, 3),
                                              Rational(1, 4), Rational(1, 8)};
  out.sigma = sigmas[random.below(sigmas.size())];
  // q_u = ⌈|A_u|/σ⌉ (curve_local.hpp): a point owned by another region adds no length, so
  // A_u is the piece in u, and a region the path does not run through has q = 0.
  out.q.assign(static_cast<std::size_t>(regions), 0);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    out.path.push_back(id(cells[i]));
    out.q[id(cells[i])] = quanta(pieces[i], out.sigma);
  }
  return out;
}

SampleCurve draw_sample_curve(const std::optional<GivenCurve>& given, bool grid_paths, int min_side,
                              int max_side, SplitMix64& random) {
  if (given)
    return {given->m, given->name, given->q};
  SampleCurve out;
  out.m = min_side +
          static_cast<int>(random.below(static_cast<std::uint64_t>(max_side - min_side + 1)));
  if (grid_paths && random.below(3) == 0) {
    GridPathCurve path = random_grid_path(out.m, random);
    out.name = path.describe();
    out.q = std::move(path.q);
  }
  return out;
}

} // namespace proofs
