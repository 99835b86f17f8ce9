#pragma once
// The grid tiling of seed 000 §4.1 (and seed 002 §II): the deployment space is an m×m
// square of b×b regions. Neighbours share a boundary: with 8-neighbourhoods (the
// journal's grid tiling, seed 000 §4.1: "Nonborder regions in this tiling have eight
// neighbors") diagonal regions count; with 4-neighbourhoods (seed 002: "the north,
// south, east, and west neighboring grid squares") they do not.
//
// Regions are numbered row by row: region u = row * m + col, row 0 at the top (the
// matrices of `tioa-check round` are printed the same way). The region graph is a
// Boost.Graph adjacency list; regDist(u, v) is the number of hops on a shortest path and
// the diameter D the largest regDist. On a grid both have closed forms (Manhattan
// distance with 4 neighbours, Chebyshev with 8); hops_from() computes them the other way,
// by breadth-first search on the graph, and the tests check that the two agree.

#include <cstdint>
#include <vector>

#include <boost/graph/adjacency_list.hpp>

namespace mc {

using RegionId = std::uint32_t;

enum class Neighbourhood { four = 4, eight = 8 };

struct Region {
  int row;
  int col;
};

class GridTiling {
public:
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;

  // m >= 1 regions per side; throws std::invalid_argument on a bad m.
  GridTiling(int m, Neighbourhood neighbourhood);

  int m() const { return m_; }
  Neighbourhood neighbourhood() const { return neighbourhood_; }
  std::size_t size() const { return static_cast<std::size_t>(m_) * static_cast<std::size_t>(m_); }

  RegionId id(int row, int col) const { return static_cast<RegionId>(row * m_ + col); }
  Region region(RegionId u) const { return {static_cast<int>(u) / m_, static_cast<int>(u) % m_}; }

  // nbrs(u), in increasing id order, and nbrs+(u) = nbrs(u) ∪ {u}.
  const std::vector<RegionId>& nbrs(RegionId u) const { return neighbours_[u]; }
  std::vector<RegionId> nbrs_plus(RegionId u) const;
  bool neighbours(RegionId u, RegionId v) const;

  RegionId reg_dist(RegionId u, RegionId v) const;
  RegionId diameter() const { return reg_dist(0, static_cast<RegionId>(size() - 1)); }
  // regDist from u to every region, by breadth-first search on the region graph.
  std::vector<RegionId> hops_from(RegionId u) const;
  const Graph& graph() const { return graph_; }

private:
  int m_;
  Neighbourhood neighbourhood_;
  Graph graph_;
  std::vector<std::vector<RegionId>> neighbours_;
};

} // namespace mc
