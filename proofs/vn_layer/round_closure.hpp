#pragma once
// round-closure: L_round (round_legal_set.hpp) as a legal set of the conference layer,
// checked in three parts (docs/design/vn-layer.md §5.3, check 4):
//   (a) every execution from the instance's start states is in L_round at time δ (the
//       first round start the VNs take part in, C12);
//   (b) closure at round granularity: from every L_round state, every execution is in
//       L_round at the next round start;
//   (c) no time-lock in the rounds from L_round states, so in Reach(L_round).
// (b) and (c) explore one representative per class of L_round (round_legal_set.hpp), and
// check that no round they explore reads what the classes ignore.

#include "checker/checks.hpp"
#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

// The name under which a model registers l_round_layer() for `replay`.
inline constexpr const char* l_round_system_name = "L_round";

// The layer started in L_round (never enumerated: the check explores one state per class):
// the automaton the traces of (b) and (c) are of, for `replay`.
tioa::Automaton l_round_layer(const tioa::Automaton& layer, const VnConfig& config);

// `system`: the layer with the instance's start states; `layer`: the same without them.
// Not checked (incomplete) with cn_faults: L_round's closure is about executions without
// CN failures, as Theorem 1's premise (002:234).
checker::PropertyResult check_round_closure(const VnConfig& config, const tioa::Automaton& layer,
                                            const tioa::Automaton& system,
                                            const checker::ExploreOptions& options, bool cn_faults);

} // namespace vn_layer
