#include "checker/explorer.hpp"

namespace checker {

const char* describe(StopReason reason) {
  switch (reason) {
  case StopReason::finished:
    return "finished";
  case StopReason::found:
    return "found";
  case StopReason::state_limit:
    return "state limit reached";
  case StopReason::time_limit:
    return "time limit reached";
  case StopReason::interrupted:
    return "interrupted";
  default:
    return "memory limit reached";
  }
}

const char* to_string(StoreKind kind) {
  return kind == StoreKind::fingerprint ? "fingerprint" : "exact";
}

template Exploration explore<NoHooks>(const tioa::SuccessorGenerator&, const tioa::StartSet&,
                                      const ExploreOptions&, const NoHooks&,
                                      const ZeroTimeReduction*);
template Exploration explore<ExploreHooks>(const tioa::SuccessorGenerator&, const tioa::StartSet&,
                                           const ExploreOptions&, const ExploreHooks&,
                                           const ZeroTimeReduction*);

} // namespace checker
