#pragma once
// A declared family of small round-level instances (models/mc/round.hpp) over which the
// one-step lemmas (6.1, 6.4) are checked exhaustively: every grid side m with its largest
// count c_m, every neighbourhood, every named curve (q per region in units of σ), every k
// and ρ2, and every configuration of counts with each region's count in 0..c_m.
//
// Symmetry. The rotations and reflections of the square (the dihedral group of order 8)
// map the region graph onto itself for both neighbourhoods, and assign depends on a
// neighbour only through its y and q, with every order of lower explored (all_flows). So
// if σ fixes q, the outcomes of the round from σ(M) are the σ-images of those from M, and
// every claim of a one-step lemma has the same verdict on both. The enumeration visits one
// configuration per orbit of the symmetries that fix q (the lexicographically smallest) and
// says how many it skipped; each visited configuration carries its orbit size, so that the
// figures can also be given for the whole unreduced family.
//
// Curves that coincide up to symmetry for a given m (on a 1×1 grid every curve is "no
// curve", "q = 1" or "q = 3") are visited once, under the first name; `settings` says
// which names were merged.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "models/mc/grid.hpp"
#include "models/mc/rational.hpp"
#include "models/mc/round.hpp"

namespace proofs {

using mc::Counts;
using mc::QuantisedLength;
using mc::RegionId;
using mc::RobotCount;

// ---- Curves as q matrices

// The named curves, in the order the default family lists them:
//   none         no region on the curve (q = 0 everywhere)
//   point        one region on the curve: the centre (row = col = ⌊(m−1)/2⌋), q = 1
//   line         a straight line across: the middle row ⌊m/2⌋, q = 1
//   L            an L shape: the left column and the bottom row, q = 1
//   ring         a full ring: every region on the border of the grid, q = 1
//   all          every region on the curve, q = 1
//   line-1-3     the middle row with q = 1, 3, 1, 3, … from the left (q_g/q_h = 3 or 1/3)
//   checker-1-3  every region, q = 1 where row + col is even and 3 where it is odd
//   hub-3        every region, q = 1, except the centre with q = 3
const std::vector<std::string>& curve_names();

// q of the named curve on an m×m grid, by RegionId (row·m + col). Throws
// std::invalid_argument for an unknown name (listing the known ones) or m < 1.
std::vector<QuantisedLength> curve_q(const std::string& name, int m);

// A curve given as its q matrix rather than by name: read from a curve file or a round
// configuration (models/mc/curve_file.hpp, round_config.hpp), or drawn by a search.
struct GivenCurve {
  std::string name; // what reports call it: "curve file c.txt", "grid path …"
  int m = 1;
  std::vector<QuantisedLength> q; // by RegionId
};

// ---- Symmetries of the square

// The 8 rotations and reflections of the m×m grid as permutations of RegionId:
// image[u] is where region u goes. Deduplicated (for m = 1 there is one); the identity first.
std::vector<std::vector<RegionId>> grid_symmetries(int m);

// Those symmetries σ with q[σ(u)] = q[u] for every u (the identity first).
std::vector<std::vector<RegionId>> symmetries_fixing(int m, const std::vector<QuantisedLength>& q);

// values∘σ: the configuration whose region u holds values[σ(u)].
template <class T>
std::vector<T> permuted(const std::vector<T>& values, const std::vector<RegionId>& sigma) {
  std::vector<T> out(values.size());
  for (std::size_t u = 0; u < values.size(); ++u)
    out[u] = values[sigma[u]];
  return out;
}

// ---- The family

struct Side {
  int m = 1;                // the grid is m×m
  RobotCount max_count = 0; // c: each region holds 0..c robots
};

struct Family {
  std::vector<Side> sides{{1, 10}, {2, 12}, {3, 3}};
  std::vector<mc::Neighbourhood> neighbourhoods{mc::Neighbourhood::four};
  std::vector<std::string> curves = curve_names();
  std::vector<RobotCount> ks{1, 2, 3};
  std::vector<mc::Rational> rho2s{{1, 2}, {9, 10}, {1, 10}, {2, 3}};
  mc::Rational rho1{1, 2}; // not used by assign (calctarget only); fixed
  bool use_symmetry = true;
  // Set: this curve instead of `curves`; every side must be its m.
  std::optional<GivenCurve> given_curve;
  // Non-empty: exactly these configurations of counts, in this order, each checked once
  // (no symmetry), instead of every configuration with counts 0..c; every side must have
  // their m. For a check along one run (`-p config=PATH`).
  std::vector<Counts> configurations;

  // The default family of the lemma checks for one neighbourhood.
  static Family standard(mc::Neighbourhood neighbourhood);
};

// One combination of the family's parameters: everything but the counts.
struct Setting {
  int m = 1;
  mc::Neighbourhood neighbourhood = mc::Neighbourhood::four;
  std::string curve;
  std::vector<QuantisedLength> q;
  RobotCount k = 1;
  mc::Rational rho2{9, 10};
  mc::Rational rho1{1, 2};
  RobotCount max_count = 0;
  // Non-empty: the only configurations of this setting (Family::configurations).
  std::vector<Counts> configurations = {};

  mc::RoundSystem system() const;
};

// One instance of a one-step lemma: a setting and the counts at the start of round t.
struct Instance {
  Setting setting;
  Counts counts;

  RobotCount robots() const { return mc::total(counts); }
};

// The settings of a family in enumeration order: sides, neighbourhoods, curves, k, ρ2
// (outermost first). A curve that equals an earlier one up to symmetry for the same m is
// left out and listed in `merged` as "name = earlier (m = …)". Throws std::invalid_argument
// on an empty list, m < 1, c < 0, an unknown curve, k < 1 or ρ2 outside (0, 1).
struct SettingList {
  std::vector<Setting> settings;
  std::vector<std::string> merged;
};
SettingList settings(const Family& family);

// Visits every configuration of a setting (counts 0..max_count per region, the last
// region's count changing fastest) that is the lexicographically smallest of its orbit
// under the symmetries fixing q — every configuration when use_symmetry is false — with
// the size of its orbit (1 without symmetry). A setting with `configurations` visits
// exactly those, each with orbit 1.
struct Coverage {
  std::uint64_t visited = 0; // configurations visited (instances checked)
  std::uint64_t skipped = 0; // symmetric duplicates not visited
  std::uint64_t total() const { return visited + skipped; }
};
Coverage
for_each_configuration(const Setting& setting, bool use_symmetry,
                       const std::function<void(const Counts&, std::uint64_t orbit)>& visit);

// How many configurations the family visits and skips, without checking anything.
Coverage count_configurations(const Family& family);

// ---- Printing

// "m ∈ {1 (counts 0..10), 2 (0..12), 3 (0..3)}, neighbourhood 4, curves {none, …}, k ∈
// {1, 2, 3}, ρ2 ∈ {1/2, 9/10, 1/10, 2/3}, every configuration of counts; …" — one line.
std::string describe(const Family& family);

// "m = 3, neighbourhood 8, curve hub-3, k = 1, rho2 = 9/10"
std::string describe(const Setting& setting);

// A matrix of values per region, one line per row, each prefixed with `indent`; zeros
// printed as "." when dots_for_zero.
std::vector<std::string> matrix_lines(int m, const std::vector<std::int64_t>& values,
                                      const std::string& indent, bool dots_for_zero);

// "(row,col)"
std::string region_name(int m, RegionId u);

std::string to_string(mc::Neighbourhood neighbourhood); // "4" or "8"

} // namespace proofs
