#pragma once
// A cheap proof that zero-time steps cannot go on for ever (no cycle of them), so that the
// greatest fixpoint System::zero_time_forever computes (one preimage of every step group per
// step of the longest zero-time run: most of a symbolic stabilisation check on VLayer[MC])
// is not needed.
//
// Two rules cut the step groups down, in turn, until neither cuts:
//  - a monotone variable: if no step of the groups left ever lowers a variable v (its code,
//    as an unsigned number), v is constant around every cycle of them (it can only rise, and
//    comes back to where it was), so each step of a cycle keeps v: the groups are cut down
//    to their steps that keep v. The same when no step ever raises v.
//  - a dead end: a group none of whose steps (those left) leads to a state where a step
//    left starts is on no cycle: it is cut out. (A CN's velocity output is one: it sets v to
//    the velocity it wants, and wants to send one only while v differs.)
// When no group has a step left, there is no cycle; otherwise nothing is proved (the
// fixpoint decides). Why it is sound: by induction over the cuts, every step of a cycle of
// the original groups is in every cut group. Measured on VLayer[MC] 1x1 (lemma-7.3,
// starts=all): the proof takes well under a second; the fixpoint it replaces took 20 s of
// 57, and on 1x2 more than a minute a round for more than 13 rounds.

#include <vector>

#include "checker/symbolic_learning.hpp"

namespace checker::symbolic {

// Whether the steps of `groups` (over `space`'s valid states) have no cycle, proved by the
// elimination above; false: not proved.
bool no_cycle_proved(const Space& space, const std::vector<StepRelation>& groups);

} // namespace checker::symbolic
