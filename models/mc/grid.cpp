#include "models/mc/grid.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <boost/graph/breadth_first_search.hpp>

namespace mc {

GridTiling::GridTiling(int m, Neighbourhood neighbourhood) : m_(m), neighbourhood_(neighbourhood) {
  if (m < 1 || m > 1000)
    throw std::invalid_argument("grid side m must be in 1..1000, not " + std::to_string(m));
  const std::size_t n = size();
  graph_ = Graph(n);
  neighbours_.resize(n);
  for (int row = 0; row < m; ++row)
    for (int col = 0; col < m; ++col)
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const bool diagonal = dr != 0 && dc != 0;
          if ((dr == 0 && dc == 0) || (diagonal && neighbourhood == Neighbourhood::four))
            continue;
          const int r = row + dr, c = col + dc;
          if (r < 0 || r >= m || c < 0 || c >= m)
            continue;
          neighbours_[id(row, col)].push_back(id(r, c));
          if (id(row, col) < id(r, c))
            boost::add_edge(id(row, col), id(r, c), graph_);
        }
  for (auto& list : neighbours_)
    std::sort(list.begin(), list.end());
}

RegionId GridTiling::reg_dist(RegionId u, RegionId v) const {
  const Region a = region(u), b = region(v);
  const int rows = std::abs(a.row - b.row), cols = std::abs(a.col - b.col);
  return static_cast<RegionId>(neighbourhood_ == Neighbourhood::four ? rows + cols
                                                                     : std::max(rows, cols));
}

std::vector<RegionId> GridTiling::hops_from(RegionId u) const {
  std::vector<RegionId> hops(size(), 0);
  boost::breadth_first_search(graph_, boost::vertex(u, graph_),
                              boost::visitor(boost::make_bfs_visitor(
                                  boost::record_distances(hops.data(), boost::on_tree_edge()))));
  return hops;
}

std::vector<RegionId> GridTiling::nbrs_plus(RegionId u) const {
  std::vector<RegionId> out = neighbours_[u];
  out.insert(std::lower_bound(out.begin(), out.end(), u), u);
  return out;
}

bool GridTiling::neighbours(RegionId u, RegionId v) const {
  return std::binary_search(neighbours_[u].begin(), neighbours_[u].end(), v);
}

} // namespace mc
