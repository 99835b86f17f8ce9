#pragma once
// The legal set L1MC of seed 000 Definition 7.1 (lines 1195–1212) as a predicate on states
// of VLayer[MC] (models/vlayer_mc/vlayer.hpp), clause by clause:
//
//   (1) x restricted to Vbcast ‖ RW ‖ VW ∈ Reach(Vbcast ‖ RW ‖ VW)
//   (2) ∀u ¬failed_u: clock_u ∈ {RW.now, ⊥} ∧ (M_u ≠ ∅ ⇒ clock_u mod δ ∈ (0, e + 2d + 2ε])
//   (3) ∀p ¬failed_p ⇒ v_p ∈ {RW.vel(p)/v_max, ⊥}
//   (4) ∀p ¬failed_p ∧ x_p ≠ ⊥:
//       (a) x_p = RW.loc(p) ∧ clock_p = RW.now
//       (b) x*_p ∈ {x_p, ⊥} ∨ ||x*_p − x_p|| < v_max(δ⌈clock_p/δ⌉ − clock_p − d_r)
//       (c) Vbcast.reg(p) = region(x_p) ∨ clock mod δ ∈ (e + 2d + 2ε, δ − d_r + ε_sample)
//
// Readings (models/vlayer_mc/README.md): clocks are phases (D15), so "= RW.now" compares
// phases and δ⌈c/δ⌉ − c is 0 at phase 0 and δ − c otherwise; v_p = RW.vel(p) (D4); the
// norm is L∞ (D8); "clock" in (4c) is clock_p; the window of (4c) is taken modulo δ when
// δ − d_r + ε_sample > δ. Clause (1) is not a predicate of one state: the checks start the
// environment in its reachable states (R(Vbcast ‖ RW ‖ VW)) instead; `clauses` reports the
// others one by one.

#include <functional>
#include <string>
#include <vector>

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// The clauses (2)–(4c) that a state breaks, as "(2) VN_1", "(4b) CN_0"; empty when in L1MC
// (up to clause (1)).
using ClauseCheck = std::function<std::vector<std::string>(const tioa::State&)>;

// The window of clause (2) for M_u ≠ ∅. As printed it is open at 0, but a cn-update vcast
// at a round start may be delivered at once (VBDelay "up to e", VBcast "within d"), also in
// dense time, so M_u ≠ ∅ at clock_u mod δ = 0 is reachable: `closed` reads it as
// [0, e + 2d + 2ε] (models/vlayer_mc/README.md, finding F1).
enum class MWindow { as_printed, closed };

ClauseCheck l1mc_clauses(const VlConfig& config, const tioa::Automaton& layer,
                         MWindow window = MWindow::as_printed);
tioa::StatePredicate l1mc(const VlConfig& config, const tioa::Automaton& layer,
                          MWindow window = MWindow::as_printed);
// L1MC as a conjunction: one predicate per clause and node ("(2) VN_u", "(3) CN_p", ...),
// each reading only what its clause reads; a state is in L1MC exactly when it satisfies
// all of them. The symbolic check builds L1MC from them, clause by clause
// (checker/symbolic_stabilisation.hpp).
std::vector<tioa::StatePredicate> l1mc_conjuncts(const VlConfig& config,
                                                 const tioa::Automaton& layer,
                                                 MWindow window = MWindow::as_printed);

} // namespace vlayer_mc
