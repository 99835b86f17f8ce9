#include "checker/level_end.hpp"

#include <algorithm>
#include <vector>

namespace checker {

std::size_t renumbering_bytes(const Discovery& discovery, std::uint64_t count) {
  return discovery.order_growth_bytes(count) + count * sizeof(StateId) + count / 8 + 64;
}

std::optional<StopReason> finish_level(std::span<const Worker> workers, const Level& level,
                                       Exploration& ex, bool record_edges, MemoryBudget& budget) {
  std::optional<StopReason> stop;
  for (const Worker& w : workers) {
    ex.edges += w.edge_count;
    ex.expanded += w.expanded;
  }
  const StateId first = level.first_new();
  Discovery& discovery = level.discovery;
  // With several workers, the ids of their blocks that no state took are holes
  // (expansion.hpp marks a block's ids as holes when it takes it).
  std::uint64_t count = ex.store.size() - first; // holes included, until renumbered

  // Breadth-first ids: the new id of the state that had id first + t (empty: the same),
  // for the edges and the targets. (The holes' entries are never read.)
  std::span<const StateId> renumbered;
  std::span<const StateId> order;
  bool target = false;
  for (const Worker& w : workers)
    target = target || !w.targets.empty();
  // A level that a limit cut short (none of its states is a target) is not put in key
  // order: which of its states got in depends on the race between the workers anyway,
  // and the renumbering of millions of states would take seconds past the limit. Its
  // holes are filled with its last states instead, which moves few. Its edges are not
  // gathered either: a run that stops so is incomplete, and no check reads the graph of
  // an incomplete run (gathering a hundred million edges takes seconds too).
  const bool cut_short = !target && (level.signals.out_of_time || level.signals.out_of_memory ||
                                     level.gate.stopped() || interrupted());
  if (level.concurrent()) { // (one worker inserted in key order and wrote the parents)
    // The level's holes must go whatever the memory limit says; past it, the run stops.
    // The states move through a copy of the level when it fits, else one at a time.
    const std::size_t bytes = renumbering_bytes(discovery, count) +
                              (level.states ? level.states->reorder_bytes(count) : 0);
    const bool in_place = !budget.fits(bytes + ex.store.reorder_copy_bytes(first));
    if (in_place && !budget.fits(bytes)) {
      budget.note(budget.held() + bytes);
      stop = StopReason::memory_limit;
    }
    const auto threads = static_cast<std::uint32_t>(workers.size());
    // The parents come with the order, from the keys (whose memory then takes the copy
    // of the level that the store's renumbering moves its states through). Room for
    // as many as the level's ids, holes included (a few): the order tells how many.
    const bool parents_fit = budget.grow_within(ex.parent, count);
    const std::size_t parents_before = ex.parent.size();
    StateId* parents = nullptr;
    if (parents_fit) {
      ex.parent.resize(parents_before + count);
      parents = ex.parent.data() + parents_before;
    }
    order = cut_short ? discovery.dense_order(count, parents)
                      : discovery.order(count, level.begin, level.end, threads, parents);
    if (parents_fit)
      ex.parent.resize(parents_before + order.size());
    if (target || (record_edges && !cut_short))
      renumbered = discovery.new_ids(order, count, threads);
    if (level.states)
      level.states->reorder(order, count);
    const std::uint64_t held = count; // holes included
    count = order.size();
    if (cut_short)
      ex.store.fill_holes(first, order, discovery.slots());
    else
      ex.store.reorder(first, order, discovery.slots(), in_place,
                       discovery.spent_keys(held * ex.store.words()));
    if (!parents_fit)
      return StopReason::memory_limit;
  }
  auto new_id = [&](StateId id) {
    return renumbered.empty() || id < first ? id : renumbered[id - first];
  };

  std::size_t stuck = 0, known = 0, fresh = 0;
  for (const Worker& w : workers) {
    stuck += w.stuck.size();
    known += w.known_edges.size();
    fresh += w.new_edges.size();
  }
  if (!budget.grow_within(ex.stuck, stuck))
    return StopReason::memory_limit;
  // In frontier order, as one worker would have found them (each took chunks in order).
  const std::size_t before = ex.stuck.size();
  for (const Worker& w : workers)
    ex.stuck.insert(ex.stuck.end(), w.stuck.begin(), w.stuck.end());
  std::sort(ex.stuck.begin() + static_cast<std::ptrdiff_t>(before), ex.stuck.end());
  if (level.states && before == 0 && !ex.stuck.empty()) { // (the store has no states)
    std::vector<Word> unpacked(ex.state_words);
    const Word* state = level.states->frontier(ex.stuck.front(), unpacked.data());
    ex.first_stuck_state.assign(state, state + ex.state_words);
  }
  if (record_edges && !cut_short) {
    // Each frontier state's steps: to states stored before the level first, then to new
    // ones, as a sequential search records them; one worker has each state's.
    if (!budget.grow_within(ex.edge_targets, known + fresh) ||
        !budget.grow_within(ex.edge_offsets, level.end - level.begin))
      return StopReason::memory_limit;
    std::vector<std::size_t> at_known(workers.size(), 0), at_new(workers.size(), 0);
    for (StateId v = level.begin; v < level.end; ++v) {
      for (std::size_t w = 0; w < workers.size(); ++w) {
        const auto& edges = workers[w].known_edges;
        for (std::size_t& i = at_known[w]; i < edges.size() && edges[i].from == v; ++i)
          ex.edge_targets.push_back(edges[i].to);
      }
      for (std::size_t w = 0; w < workers.size(); ++w) {
        const auto& edges = workers[w].new_edges;
        for (std::size_t& i = at_new[w]; i < edges.size() && edges[i].from == v; ++i)
          ex.edge_targets.push_back(edge_to(new_id(edges[i].target()), edges[i].duration()));
      }
      ex.edge_offsets.push_back(ex.edge_targets.size());
    }
  }

  std::optional<StateId> found;
  for (const Worker& w : workers)
    for (StateId t : w.targets)
      if (!found || new_id(t) < *found)
        found = new_id(t);
  if (found) {
    // A sequential search stops at the target: what it would not have inserted goes.
    ex.store.truncate(std::uint64_t{*found} + 1);
    ex.parent.truncate(std::uint64_t{*found} + 1);
    if (record_edges) { // the steps to states forgotten go too
      std::uint64_t kept = 0, begin = 0;
      for (std::size_t v = 0; v + 1 < ex.edge_offsets.size(); ++v) {
        const std::uint64_t end = ex.edge_offsets[v + 1];
        for (std::uint64_t i = begin; i < end; ++i)
          if ((ex.edge_targets[i] & ~Edge::timed_bit) <= *found)
            ex.edge_targets[kept++] = ex.edge_targets[i];
        begin = end;
        ex.edge_offsets[v + 1] = kept;
      }
      ex.edge_targets.resize(kept);
    }
    ex.found = found;
    if (level.states) {
      ex.found_state.resize(ex.state_words);
      level.states->built(*found, ex.found_state.data());
    }
    return StopReason::found;
  }
  if (stop)
    return stop;
  if (level.signals.state_limit)
    return StopReason::state_limit;
  if (level.gate.stopped())
    return StopReason::memory_limit;
  return std::nullopt;
}

} // namespace checker
