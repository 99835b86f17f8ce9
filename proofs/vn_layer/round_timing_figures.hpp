#pragma once
// The measured figures of round-timing (docs/design/vn-layer.md §5.3, check 2): the worst
// times the layer's messages and CNs take, against the ones seed 002 §V-B states, over
// every step of every reachable state. (T1)–(T4) are checked as invariants; these say how
// much slack each claim has.
//
//  - cn-update: from its round's start (phase 0, when the CN sends it) to its delivery at
//    the VN, against d_v; the VN reads the exchange-trigger at d_v + ε at the earliest.
//  - vn-update: from its round's start to its delivery at the neighbour VN, against
//    d_MMT + 3d_v + ε; the target-trigger comes at d_MMT + 3d_v + 2ε (002:158).
//  - target-update: from the CN's target-trigger (phase d_MMT + 3d_v + 2ε) to its
//    delivery at the CN, against d_MMT + 2d_v (002:160).
//  - arrival: the phase of the tick that brings a CN onto its target, δ for the tick that
//    begins the next round, against δ (002:162: on target at every round start).
// A VN's restart has no figure: a restart at phase 0 may close the last round or follow a
// CN that enters a zone in passing, and (T4) checks the VNs that matter at each round
// start.
// A delivery's round is the round tag it carries (an age: 0 this round, 1 the last, C23),
// so one delivered after its round ended counts from its own round's start.

#include "checker/checks.hpp"
#include "models/vn_layer/config.hpp"

namespace vn_layer {

// Explores the layer again and adds the figures to `r` ("... measured", "... stated"), with
// a note; on a run cut short by a limit, a note that says they were not measured.
void add_round_timing_figures(const VnConfig& config, const tioa::Automaton& system,
                              const checker::ExploreOptions& options, checker::PropertyResult& r);

} // namespace vn_layer
