#pragma once
// stabilisation (docs/design/vn-layer.md §5.3, check 6): Theorem 1 of seed 002 §VI measured
// in the timed layer, round by round, on every execution from every start state.
//
//   Theorem 1 (002:234–238): "If there are no failures or recoveries of client nodes at or
//   after some round t_0, then within a finite number of rounds after t_0: (1) the set of
//   CNs assigned to each VN_h … becomes fixed, … and (2) all client nodes in B_h for which
//   q_h ≠ 0 are located on Γ_h …"
//   002:302: "From line 33 of Figure 7, it follows immediately that by the beginning of
//   round T_stab + 2, all CNs in C_in are located on the curve Γ."
//
// The check claims what the paper states with a time or a bound: (1) on every execution the
// assignment becomes fixed (T_stab is finite), within Lemma 6's proportionality bound at
// every round start from which it may stay fixed (assignment_measures.hpp), and (2) from
// round T_stab + 2 on, every active CN in a zone with q_h ≠ 0 stands on Γ_h. The
// conference gives no bound on T_out or T_stab (002:234, 264, 286), so their worst values
// are measured and set beside the round-level system's from the same start counts, not
// judged. Lemma 7's even spacing "in the limit" is measured at the round starts on cycles
// of rounds, not judged: the lattice rounds calctarget's points down, so a limit point can
// stop short of its place (the exact limit is mc-round's lemma-6.8).

#include <cstdint>
#include <vector>

#include "checker/checks.hpp"
#include "models/vn_layer/config.hpp"

namespace vn_layer {

// The round-level system's T_stab from `start_counts` (counts per zone at time 0), in the
// layer's numbering: the first round from which the counts at round starts stay fixed, the
// layer's rounds 0 and 1 both holding the start counts (the VNs skip round 0, C12);
// `unbounded` (round_graph.hpp) when the counts cycle.
std::uint32_t round_level_t_stab(const VnConfig& config, const std::vector<int>& start_counts);

// Violated with a lasso: an execution whose assignment changes for ever (1), one whose
// assignment stays fixed beyond the proportionality bound (1), or one whose assignment
// stays fixed from round T on while a CN of C_in is off Γ at round T + 2 or later (2).
// `cn_faults`: CNs fail and recover (outside the theorem's premise after t_0; the check is
// not run: incomplete).
checker::PropertyResult check_stabilisation(const VnConfig& config, const tioa::Automaton& system,
                                            const checker::ExploreOptions& options, bool cn_faults);

} // namespace vn_layer
