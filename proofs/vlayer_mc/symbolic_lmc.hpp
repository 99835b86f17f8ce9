#pragma once
// LMC as far as it is known (KnownLmc, D29) as a set of states for the symbolic checks: the
// states whose representative is one of the known classes. The representative forgets, part
// by part (KnownLmc::forgetting), what nothing reads again; so the set is the classes' states
// taken back through each part in turn, the last part first: where a part applies, the
// forgotten variables may hold anything the class's state at their initial codes allows.

#include "checker/symbolic_learning.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"

namespace vlayer_mc {

// Every state of `space` (the states of the layer `known` was built on) that
// KnownLmc::contains.
bdd known_lmc_set(const checker::symbolic::Space& space, const KnownLmc& known,
                  checker::symbolic::LearningFigures& figures);

} // namespace vlayer_mc
