#pragma once
// The layer seen at its round starts (docs/design/vn-layer.md §5.3, checks 5 and 6). A round
// start is a start state (round 0, at time 0) or a state a tick enters at phase 0 (realtime
// kδ, before any round-k message: the cn-update is an urgent output of that instant). The
// states of a round are those reached from its round start without a tick into the next
// round start; the rounds it leads to are the round starts those ticks enter.

#include <cstdint>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/trace.hpp"
#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

// The layer's variables read at a round start: the round phase (CN_0's copy of realtime mod
// δ, C21: with no CN failures every copy is the same) and each CN's failed flag and
// position.
struct RoundView {
  RoundView(const tioa::Automaton& system, const VnConfig& config);

  // The active CNs per zone, indexed by region.
  std::vector<int> counts(const tioa::Word* state) const;
  // Each CN's zone, or −1 for a failed CN.
  std::vector<int> zones(const tioa::Word* state) const;
  // Each CN's point, or −1 for a failed CN.
  std::vector<int> points(const tioa::Word* state) const;
  bool round_begins(const tioa::Word* state) const;

  Lattice lattice;
  tioa::Variable<int> phase;
  std::vector<tioa::Variable<bool>> failed;
  std::vector<tioa::Variable<int>> x;
};

// Searches rounds of a complete exploration with edges (`hooks.record_edges`).
class RoundWalker {
public:
  RoundWalker(const checker::Exploration& ex, const RoundView& view);

  // A start state or a state a tick enters at phase 0.
  bool is_round_start(checker::StateId v) const {
    return v < ex_.start_states || later_start_[v] != 0;
  }
  // Entered by a tick at phase 0 (round k ≥ 1). A state may be a start state as well.
  bool is_later_start(checker::StateId v) const { return later_start_[v] != 0; }

  // Searches the round that begins at `start` breadth first and calls `on_end(from, to)` for
  // every tick from one of its states `from` into a round start `to`; stops when `on_end`
  // returns false. Returns false when it was stopped.
  template <class OnEnd> bool walk(checker::StateId start, OnEnd on_end) {
    ++walks_;
    queue_.assign(1, start);
    seen_in_[start] = walks_;
    for (std::size_t next = 0; next < queue_.size(); ++next) {
      const checker::StateId v = queue_[next];
      for (const std::uint32_t t : ex_.steps_from(v)) {
        const checker::StateId to = t & ~checker::Edge::timed_bit;
        if ((t & checker::Edge::timed_bit) && later_start_[to]) {
          if (!on_end(v, to))
            return false;
          continue;
        }
        if (seen_in_[to] == walks_)
          continue;
        seen_in_[to] = walks_;
        came_from_[to] = v;
        queue_.push_back(to);
      }
    }
    return true;
  }
  // The states of the last walk from its round start (excluded) to `v` (included), in order.
  std::vector<checker::StateId> path_within(checker::StateId start, checker::StateId v) const;

private:
  const checker::Exploration& ex_;
  std::vector<std::uint8_t> later_start_;
  std::uint32_t walks_ = 0;
  std::vector<std::uint32_t> seen_in_; // the walk that reached it last
  std::vector<checker::StateId> came_from_;
  std::vector<checker::StateId> queue_;
};

// Appends one round to `trace`, whose last state is the round's start: the states
// `within` it (in order), then the tick into the round start `to`. Throws when a step is
// no step of the model (the states come from the graph, so that is a bug).
void extend_by_round(const tioa::SuccessorGenerator& generator, const checker::Exploration& ex,
                     checker::Trace& trace, const std::vector<checker::StateId>& within,
                     checker::StateId to);

} // namespace vn_layer
