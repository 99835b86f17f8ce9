#include "checker/merge.hpp"

namespace checker {

namespace {
// Candidates ahead whose slot in the store is prefetched.
constexpr std::size_t prefetch_distance = 8;
} // namespace

std::optional<StopReason> merge_level(std::span<const Worker> workers, Exploration& ex,
                                      Insertion& insertion, MemoryBudget& budget,
                                      std::vector<StateId>& next) {
  const bool record_edges = insertion.records_edges();
  for (const Worker& w : workers) {
    ex.edges += w.edge_count;
    ex.expanded += w.expanded;
  }
  for (const Worker& w : workers) {
    if (!budget.grow_within(ex.stuck, w.stuck.size()) ||
        (record_edges && !budget.grow_within(ex.edge_list, w.edges.size())))
      return StopReason::memory_limit;
    ex.stuck.insert(ex.stuck.end(), w.stuck.begin(), w.stuck.end());
    if (record_edges)
      ex.edge_list.insert(ex.edge_list.end(), w.edges.begin(), w.edges.end());
  }
  for (const Worker& w : workers) {
    for (std::size_t c = 0; c < w.candidates.size(); ++c) {
      if (c + prefetch_distance < w.candidates.size())
        ex.store.prefetch(w.candidates[c + prefetch_distance].hash);
      const Candidate& candidate = w.candidates[c];
      const auto [outcome, id] =
          insertion.insert(w.states[c], candidate.hash, candidate.from, next);
      if (outcome == Insertion::Outcome::state_limit)
        return StopReason::state_limit;
      if (outcome == Insertion::Outcome::memory_limit)
        return StopReason::memory_limit;
      if (record_edges)
        ex.edge_list.push_back({candidate.from, edge_to(id, candidate.duration)});
      if (outcome == Insertion::Outcome::known)
        continue;
      if (candidate.target) {
        ex.found = id;
        return StopReason::found;
      }
    }
  }
  return std::nullopt;
}

} // namespace checker
