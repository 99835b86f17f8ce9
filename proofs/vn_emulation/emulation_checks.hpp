#pragma once
// Theorem 2 of seed 002 (§VIII, 002:354–362) and the replica consistency its proof rests
// on, as checks on every state the one-zone emulation reaches
// (docs/design/vn-emulation.md §3–4; models/vn_emulation/README.md).

#include "checker/checks.hpp"
#include "models/vn_emulation/emulation.hpp"

namespace vn_emulation {

// Time can always pass: no reachable state without a step or a tick (P8).
checker::PropertyResult check_no_timelock(const Emulation& emulation,
                                          const checker::ExploreOptions& options);
// P1: wherever time can pass, the active replicas of the zone hold the same VN state and
// have nothing pending. Violated with a shortest trace to two replicas that differ.
checker::PropertyResult check_replica_consistency(const Emulation& emulation,
                                                  const checker::ExploreOptions& options);
// Theorem 2's figures, measured as worst cases over every reachable state and set against
// the stated ones: d_MMT = 2d_p + 2ε (the VN's send task), d_r = 4d_p + 5ε (start-up),
// d_v = 2d_p + ε (a client message to the VN, a VN message to the clients). Violated
// with a shortest trace to the first state past a stated figure; holds with a witness of
// the figure nearest its bound. `emulation` must be built with EmuConfig::delivery_monitor;
// its traces are cut to the emulation without the monitor's ghosts. On the fingerprint
// store the search stops at the first state past a stated figure (the worst figures are
// then those met before it), and the witness of a figure that holds reaches a state with
// its worst value (the one with the least fingerprint), not the nearest one.
checker::PropertyResult check_theorem_2(const Emulation& emulation,
                                        const checker::ExploreOptions& options);
// P7: the emulation implements the abstract VN_0 (models/vn_emulation/refinement.hpp):
// no transmission the abstract VN could not make, and wherever time can pass every active
// replica holds the abstract VN's state. `emulation` must be built with
// EmuConfig::refinement_monitor.
checker::PropertyResult check_refinement(const Emulation& emulation,
                                         const checker::ExploreOptions& options);
// P6: no reset restarts a live VN_0 (F4 of the specification). Violated with a shortest
// trace to the restart. Needs the refinement monitor too.
checker::PropertyResult check_no_live_restart(const Emulation& emulation,
                                              const checker::ExploreOptions& options);

} // namespace vn_emulation
