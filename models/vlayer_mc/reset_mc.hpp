#pragma once
// The reset states ResetMC of seed 000 Definition 7.2 (lines 1233–1247) as a predicate on
// states of VLayer[MC], clause by clause:
//
//   (1) x ∈ L1MC
//   (2) ∀p ¬failed_p ⇒ [to_send_p^− = to_send_p^+ = λ ∧ (x_p = ⊥ ∨ (x*_p ≠ ⊥ ∧ v_p = 0))]
//   (3) ∀u ¬failed_u ⇒ to_send_u = λ
//   (4) ∀⟨m, u, t, P′⟩ ∈ vbcastq: P′ = ∅
//   (5) RW.now mod δ = 0 ∧ ∀p ∀⟨l, t⟩ ∈ RW.updates(p): t < RW.now
//
// Readings (models/vlayer_mc/README.md, "Variables of Definitions 7.1 and 7.2"): to_send_p^±
// is VBDelay_p's slot (`delay.held`); to_send_u is VN_u's send buffer `out` (D7: its
// VBDelay is the identity); P′ = ∅ is "no pending bit in any VBcast slot"; (5)'s updates
// condition is gps_age[p] ≥ 1. (1) uses the L1MC window the caller picks (finding F1).

#include "models/vlayer_mc/l1mc.hpp"

namespace vlayer_mc {

// The clauses (1)–(5) a state breaks ("(1) (2) VN_0" for an L1MC clause), empty in ResetMC.
ClauseCheck reset_mc_clauses(const VlConfig& config, const tioa::Automaton& layer,
                             MWindow window = MWindow::as_printed);
tioa::StatePredicate reset_mc(const VlConfig& config, const tioa::Automaton& layer,
                              MWindow window = MWindow::as_printed);

// D30: ResetMC, or a state that differs from a ResetMC state z only in that some live robots
// with x_p ≠ ⊥ and v_p = 0 have no target (x*_p = ⊥) while their cn-update is still due at
// this phase-0 instant (a robot whose VSA sent it nothing last round; finding F6). z is the
// state with x*_p := x_p. Until the cn-update, which comes before time passes, x*_p is read
// only through the desired velocity (0 on both sides) and GPSupdate's (4b) test (met by
// x*_p = x_p); the vcast sets x*_p := ⊥ on both sides. So every execution from such a state
// is, from its cn-updates on (the same instant), an execution from z: in LMC.
tioa::StatePredicate reset_mc_or_targetless(const VlConfig& config, const tioa::Automaton& layer,
                                            MWindow window = MWindow::as_printed);

// The same as a conjunction: L1MC's conjuncts (l1mc_conjuncts), then one per client (its
// clause (2) or D30's exception), one per VSA (3), one per VBcast pending flag (4) and (5).
// Each reads only what its clause reads; the symbolic checks build the set from them.
std::vector<tioa::StatePredicate>
reset_mc_or_targetless_conjuncts(const VlConfig& config, const tioa::Automaton& layer,
                                 MWindow window = MWindow::as_printed);

} // namespace vlayer_mc
