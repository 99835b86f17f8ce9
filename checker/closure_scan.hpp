#pragma once
// The scan behind the legal-set check (checks.hpp): every valuation that satisfies `legal`,
// in the odometer's order (tioa/start_set.hpp), and every step from it; the scan stops at
// the first step out of the set (the first member in that order, its first such step).
// One process scans alone (legal_set.cpp); a distributed run (collective.hpp) shares the valuations
// among the ranks and stops where one process would, with the same counts.

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "checker/collective.hpp"
#include "checker/options.hpp"
#include "tioa/successors.hpp"

namespace checker {

struct ClosureScan {
  std::uint64_t members = 0; // members of the set scanned (up to the first step out)
  std::uint64_t edges = 0;   // the steps from them
  std::optional<std::vector<tioa::Word>> bad_from, bad_to; // the first step out
  std::string limit; // why the scan stopped early ("" when it did not)
};

using ScanClock = std::chrono::steady_clock;

// The scan (legal_set.cpp has the one of one process) with the valuations shared among the ranks:
// valuation i is tried by rank i mod ranks; every 65,536 valuations the ranks agree on the first
// step out, the state limit and the time limit, and stop together where one process stops.
ClosureScan scan_closure_distributed(const tioa::SuccessorGenerator& generator,
                                     const tioa::StateLayout& layout,
                                     const tioa::StatePredicate& legal, const Limits& limits,
                                     ScanClock::time_point began, Collective& ranks);

} // namespace checker
