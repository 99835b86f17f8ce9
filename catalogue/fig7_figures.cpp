#include "catalogue/fig7_figures.hpp"

#include <cstring>

#include "checker/collective.hpp"

namespace catalogue {

namespace {

// How often each branch of Fig. 7 fired in the property's explorations, as figures
// (branch_tally.hpp: distinct computations, robots per rule of calctarget).
void add_fig7_figures(const vlayer_mc::BranchCounts& n, checker::PropertyResult& r) {
  const auto figure = [&](const char* name, std::uint64_t value) {
    r.figures.emplace_back(name, std::to_string(value));
  };
  figure("Fig. 7 computations (distinct)", n.computations);
  figure("Fig. 7 lines 7-12 on the curve, reassigning", n.on_curve);
  figure("Fig. 7 lines 13-18 no curve neighbour, reassigning", n.no_curve_neighbour);
  figure("Fig. 7 lines 19-22 boundary, reassigning", n.boundary);
  figure("Fig. 7 lines 30-31 robots to a neighbour's centre", n.to_centre);
  figure("Fig. 7 lines 32-33 robots onto the curve", n.onto_curve);
  figure("Fig. 7 lines 35-36 robots to an end", n.to_end);
  figure("Fig. 7 line 38 robots between neighbours", n.between);
  figure("Fig. 7 robots off the curve staying", n.stays);
}

// The computations every rank of a distributed run recorded, on every rank.
std::vector<vlayer_mc::BranchRecord> gathered(checker::Collective& ranks,
                                              const std::vector<vlayer_mc::BranchRecord>& mine) {
  const std::vector<std::int32_t> words = vlayer_mc::encode(mine);
  std::vector<std::uint8_t> bytes;
  checker::append_bytes(bytes, words.data(), words.size() * sizeof(std::int32_t));
  std::vector<std::uint64_t> sizes;
  const std::vector<std::uint8_t> all = ranks.all_gather(bytes, sizes);
  std::vector<std::int32_t> in(all.size() / sizeof(std::int32_t));
  std::memcpy(in.data(), all.data(), in.size() * sizeof(std::int32_t));
  return vlayer_mc::decode(in);
}

} // namespace

// `property` counting, in an epoch of its own, the branches of Fig. 7 its explorations
// take. Over several processes each records the computations it made; the figures count
// the distinct ones over all of them, as one process would.
checker::Property counting_fig7(checker::Property property,
                                std::shared_ptr<vlayer_mc::BranchTally> tally) {
  property.run = [run = std::move(property.run), tally](const checker::ExploreOptions& o) {
    tally->start_epoch();
    checker::PropertyResult r = run(o);
    checker::Collective* ranks = checker::distributed();
    add_fig7_figures(
        ranks ? vlayer_mc::sum_distinct(gathered(*ranks, tally->records())) : tally->counts(), r);
    return r;
  };
  return property;
}

} // namespace catalogue
