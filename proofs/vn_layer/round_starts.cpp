#include "proofs/vn_layer/round_starts.hpp"

#include <algorithm>
#include <stdexcept>

#include "models/vn_layer/names.hpp"
#include "tioa/operators.hpp"

namespace vn_layer {

using checker::Edge;
using checker::StateId;

RoundView::RoundView(const tioa::Automaton& system, const VnConfig& c)
    : lattice(c.lattice()), phase(tioa::find_variable<int>(system, names::cn_name(0) + ".phase")) {
  for (int i = 0; i < c.cns; ++i) {
    failed.push_back(tioa::find_variable<bool>(system, names::cn_name(i) + ".failed"));
    x.push_back(tioa::find_variable<int>(system, names::cn_name(i) + ".x"));
  }
}

std::vector<int> RoundView::counts(const tioa::Word* state) const {
  std::vector<int> out(static_cast<std::size_t>(lattice.regions()), 0);
  for (const int zone : zones(state))
    if (zone >= 0)
      ++out[static_cast<std::size_t>(zone)];
  return out;
}

std::vector<int> RoundView::zones(const tioa::Word* state) const {
  std::vector<int> out = points(state);
  for (int& p : out)
    if (p >= 0)
      p = lattice.region_of(p);
  return out;
}

std::vector<int> RoundView::points(const tioa::Word* state) const {
  const tioa::State s(state, 0);
  std::vector<int> out(x.size(), -1);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!s[failed[i]])
      out[i] = s[x[i]];
  return out;
}

bool RoundView::round_begins(const tioa::Word* state) const {
  return tioa::State(state, 0)[phase] == 0;
}

RoundWalker::RoundWalker(const checker::Exploration& ex, const RoundView& view)
    : ex_(ex), later_start_(ex.store.size(), 0), seen_in_(ex.store.size(), 0),
      came_from_(ex.store.size(), checker::no_parent) {
  const StateId n = ex.store.size();
  checker::StateReader read(ex);
  for (StateId v = 0; v < n; ++v)
    for (const std::uint32_t t : ex.steps_from(v))
      if ((t & Edge::timed_bit) && view.round_begins(read(t & ~Edge::timed_bit)))
        later_start_[t & ~Edge::timed_bit] = 1;
}

std::vector<StateId> RoundWalker::path_within(StateId start, StateId v) const {
  std::vector<StateId> path;
  for (StateId w = v; w != start; w = came_from_[w])
    path.push_back(w);
  std::reverse(path.begin(), path.end());
  return path;
}

void extend_by_round(const tioa::SuccessorGenerator& generator, const checker::Exploration& ex,
                     checker::Trace& trace, const std::vector<StateId>& within, StateId to) {
  bool extended = true;
  checker::StateReader read(ex);
  for (const StateId w : within)
    extended = extended && checker::extend(generator, trace, read(w));
  extended = extended && checker::extend(generator, trace, read(to), 1u);
  if (!extended)
    throw std::logic_error("vn-layer rounds: an edge of the graph is no step of the model");
}

} // namespace vn_layer
