#pragma once
// The checks that run over the ranks of a distributed run (distributed_explorer.hpp), with
// the results one process gives: check_invariant and check_no_deadlock take this route
// when distributed() is set.

#include <string>

#include "checker/collective.hpp"
#include "checker/result.hpp"
#include "checker/zero_time_reduction.hpp"
#include "tioa/start_set.hpp"
#include "tioa/successors.hpp"

namespace checker {

// `reduction`: the partial-order reduction the check uses (null: none), as one process's.
PropertyResult check_invariant_distributed(const tioa::SuccessorGenerator& generator,
                                           const tioa::StartSet& start,
                                           const tioa::StatePredicate& invariant,
                                           const ExploreOptions& options,
                                           const ZeroTimeReduction* reduction, Collective& ranks);
PropertyResult check_no_deadlock_distributed(const tioa::SuccessorGenerator& generator,
                                             const tioa::StartSet& start,
                                             const tioa::StatePredicate& ended,
                                             const std::string& ended_name,
                                             const ExploreOptions& options,
                                             const ZeroTimeReduction* reduction, Collective& ranks);

} // namespace checker
