#pragma once
// Random curve shapes for the seeded searches of the round-level lemmas (issue 19): simple
// polylines that run through the grid's regions as a self-avoiding path, so that a search
// meets the curves a researcher draws and not only the named ones of proofs/family.hpp.
//
// The path visits regions r_0, r_1, …, r_L, each once (seed 000 §5.1 assumes every A_u
// convex, so a curve never re-enters a region). A step goes to one of the 8 regions around
// (a 4-neighbour, or a diagonal one through the grid vertex they share), so a path can pass
// through grid vertices, turn, and leave a row and come back to it further on. The polyline
// (b = 1, y downward as in models/mc/curve.hpp):
//   - starts at a lattice point strictly inside r_0 (denominator 8), and in each region goes
//     through one such point: its length in the region, and so q, varies (winding);
//   - crosses a shared side at a lattice point strictly inside that side, and passes a
//     diagonal step through the shared vertex;
//   - ends at a point inside r_L.
// A vertex is passed at most once. Under the ownership rule of models/mc/curve_local.hpp a
// grid vertex belongs to the region south-east of it; a step through a vertex owned by a
// third region (the anti-diagonal steps) makes that region's A_u the single vertex (q = 0),
// and the path never enters that region afterwards.
//
// q_u = ⌈|A_u|/σ⌉ is computed exactly in rationals (a piece has at most two segments of
// irrational length, and r + √a + √b ≤ c is decided by squaring twice), with σ drawn from
// {1, 1/2, 1/3, 1/4, 1/8} (units of b): pieces of about 1/4 to 2 give q from 1 to about 16.
// mc::CurveOnGrid computes the same q (random_curve_test.cpp checks it); it is not used
// here because its certified 100-digit arithmetic takes milliseconds a path, and a search
// draws thousands.

#include <optional>
#include <string>
#include <vector>

#include "models/mc/curve.hpp"
#include "models/mc/round.hpp"
#include "proofs/family.hpp"
#include "proofs/split_mix64.hpp"

namespace proofs {

struct GridPathCurve {
  std::vector<mc::RationalPoint> vertices; // the polyline
  mc::Rational sigma;                      // σ, in units of the region side b = 1
  std::vector<mc::RegionId> path;          // r_0 … r_L
  std::vector<mc::QuantisedLength> q;      // q_u / σ by RegionId
  std::size_t vertex_steps = 0;            // diagonal steps, through a grid vertex
  std::size_t rows_reentered = 0;          // rows the path leaves and later enters again

  // The polyline as a curve (its checks of simplicity run here, not when q is computed).
  mc::Curve curve() const;
  // "a grid path through 7 regions (2 steps through a vertex, re-enters 1 row), sigma = 1/4"
  std::string describe() const;
};

// How a path is drawn. axis_parallel: only steps to the 4-neighbours, and inside each region
// legs parallel to the axes (entry, a corner or two, exit) instead of the straight legs
// through an inner point: every length is then rational, as positions need
// (models/mc/exact_local_curve.hpp).
struct GridPathShape {
  bool axis_parallel = false;
};

// A random simple grid path on the m×m grid (m >= 1) and its q. Its length is drawn from
// three shapes (each a third of the draws): short (1..m regions), medium (up to m²/2) and
// as long as the walk goes (up to m²); a walk that runs into its own trail stops there.
// Deterministic in `random`'s state.
GridPathCurve random_grid_path(int m, SplitMix64& random, GridPathShape shape = {});

// The grid side and the curve of one sample of a search (both searches draw them alike): the
// given curve and its side; else m in min_side..max_side and, with grid_paths, a random grid
// path a third of the time. An empty `name`: the caller draws one of its named curves.
struct SampleCurve {
  int m = 1;
  std::string name;
  std::vector<mc::QuantisedLength> q;
};
SampleCurve draw_sample_curve(const std::optional<GivenCurve>& given, bool grid_paths, int min_side,
                              int max_side, SplitMix64& random);

} // namespace proofs
