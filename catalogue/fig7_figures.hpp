#pragma once
// How often each branch of seed 002 Fig. 7 (assign and calctarget) fired in a property's
// explorations, as the property's figures: for the models whose VNs compute targets with
// vlayer_mc::TargetMemo (vlayer-mc, vn-layer), which counts in a BranchTally.

#include <memory>

#include "checker/property.hpp"
#include "models/vlayer_mc/branch_tally.hpp"

namespace catalogue {

// `property` counting, in an epoch of its own, the branches of Fig. 7 its explorations
// take. Over several processes each records the computations it made; the figures count
// the distinct ones over all of them, as one process would.
checker::Property counting_fig7(checker::Property property,
                                std::shared_ptr<vlayer_mc::BranchTally> tally);

} // namespace catalogue
