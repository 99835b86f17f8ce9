#pragma once
// round-refinement (docs/design/vn-layer.md §5.3, check 5): the conference layer, seen at
// its round starts, is the round-level algorithm. At every round start reached (realtime
// kδ, the instant a tick begins, before any round-k message), the active CNs' counts per
// zone are those the round-level system gives from the counts at the round start before:
// each zone's VN runs assign on its count and its neighbours' (the default order, lower
// regions by increasing id, as the layer's VNs do), the CNs it reassigns land in the
// neighbour's zone, and the others stay in their zone. Round 0 is skipped by the VNs
// (C12), so from a start state the counts must stay as they are.
//
// This is the claim that carries mc-round's count-level lemmas over to the timed layer:
// it holds exactly when every VN computes on the counts of the round start (the same
// snapshot, through the cn-updates and vn-updates of the round) and every reassigned CN
// arrives before the next round starts.

#include <vector>

#include "checker/checks.hpp"
#include "models/vn_layer/config.hpp"

namespace vn_layer {

// The counts per zone one round later at count level (the reference): assign per zone
// (default order) on `counts`, indexed by region.
std::vector<int> counts_after_round(const VnConfig& config, const std::vector<int>& counts);

// The CNs' points one round later at position level (the reference of position-refinement):
// each zone's VN runs assign and calctarget (vlayer_mc::compute_targets) on the points of
// the CNs in its zone and its neighbours' counts; `positions` per CN, −1 for a failed one.
std::vector<int> positions_after_round(const VnConfig& config, const std::vector<int>& positions);

// Every round start reached against the round before; violated with a trace from a start
// state through the round start before to the first round start whose counts differ.
// `cn_faults`: CNs fail and recover (then the counts of active CNs follow no round-level
// system, and the check is not run: incomplete).
checker::PropertyResult check_round_refinement(const VnConfig& config,
                                               const tioa::Automaton& system,
                                               const checker::ExploreOptions& options,
                                               bool cn_faults);

// position-refinement: the same with the CNs' points against positions_after_round. Where
// calctarget sends a CN onto a border the next zone owns (V4), the counts leave the
// count-level system but the points follow this one.
checker::PropertyResult check_position_refinement(const VnConfig& config,
                                                  const tioa::Automaton& system,
                                                  const checker::ExploreOptions& options,
                                                  bool cn_faults);

} // namespace vn_layer
