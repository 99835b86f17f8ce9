#pragma once
// Theorem 7.8 of seed 000 (journal), on VLayer[MC].
//
// Seed 000 (journal), §7.3, lines 1336–1338:
//   "THEOREM 7.8. The traces of VLNodes[MC], starting in an arbitrary state and executed
//    with automaton R(Vbcast‖RW‖VW), stabilize in time δ+d+e+ε_sample to reachable traces
//    of R(VLayer[MC])."
// The paper proves it by composition (lines 1300–1335): Theorem 7.5 brings the system into
// LMC within δ + d + e + ε_sample; Lemma 7.7 relates every ResetMC state (so every LMC
// state) by R_MC to a reachable state of VLayer[MC]; Lemma 7.6 makes R_MC a simulation
// relation, so every trace from an LMC state is a trace from a reachable state: "a
// reachable trace of VLayer[MC]".
//
// Checked the same way: the three properties run on the instance, and the theorem's
// verdict is their conjunction. Violated when one of them is violated (the first of 7.5,
// 7.7, 7.6, with its trace and notes: the step of the proof that breaks); holds only when
// all three hold; otherwise incomplete, with each part's verdict and coverage in the notes.
// Its coverage is Theorem 7.5's (the theorem quantifies over arbitrary start states, as 7.5
// does); each part's coverage is in the notes.

#include "checker/result.hpp"

namespace vlayer_mc {

// The theorem from the results of theorem-7.5, lemma-7.6 and lemma-7.7 on one instance.
checker::PropertyResult theorem_7_8(const checker::PropertyResult& theorem_7_5,
                                    const checker::PropertyResult& lemma_7_6,
                                    const checker::PropertyResult& lemma_7_7);

} // namespace vlayer_mc
