#pragma once
// A curve for the round-level system read from a text file (`-p curve_file=PATH` of
// mc-round), one statement a line; '#' starts a comment, blank lines are ignored. Either
//
//   a q matrix: m lines of m entries, each a whole number (q_u in units of σ) or '.' for a
//   region off the curve, row 0 at the top as `tioa-check round` prints it:
//       . 1 1 .
//       . . 2 .
//
// or a polyline on the m×m grid of regions of side 1 (y grows downward, as in curve.hpp),
// whose q the tool computes (models/mc/curve_local.hpp, q_u = ⌈|A_u|/σ⌉):
//       grid 6                          the grid side m (required)
//       sigma 1/4                       σ in units of the region side (default 1)
//       polyline (0.5,0.5) (3.5,0.5)    vertices (x,y), exact rationals; further
//       polyline (3.5,2.5)              `polyline` lines add vertices to the same curve
//       closed                          the last vertex joins the first
//
// The curve must be simple and meet every region in one piece (seed 000 §5.1 assumes A_u
// convex): Curve and CurveOnGrid say why not.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "models/mc/curve.hpp"
#include "models/mc/rational.hpp"

namespace mc {

struct CurveFile {
  int m = 1;
  std::vector<std::int64_t> q;   // q_u / σ by RegionId (row·m + col)
  std::optional<Curve> polyline; // when the file gives a polyline (regions of side 1)
  Rational sigma = 1;            // with a polyline
};

// The largest grid side a curve file may give (the round-level searches go to 12).
inline constexpr int max_curve_file_side = 50;

// Every error throws std::invalid_argument with one line "<source>:<line>: <what is wrong>",
// or "<source>: <what is wrong>" when no line is to blame (cannot read, no curve, a curve
// that is not simple or leaves the grid).
CurveFile read_curve_file(const std::string& path);
CurveFile parse_curve_file(std::istream& in, const std::string& source);

} // namespace mc
