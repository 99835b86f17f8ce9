#pragma once
// The exit codes scripts rely on.

#include <vector>

#include "checker/result.hpp"

namespace cli {

enum ExitStatus : int {
  all_hold = 0,
  some_violated = 1,   // (suite: some definite verdict differs from its expected verdict)
  usage_error = 2,     // bad command line or input: unknown model, parameter, property...
  some_incomplete = 3, // a limit was hit and nothing was violated
};

struct VerdictCounts {
  std::size_t holds = 0, violated = 0, incomplete = 0;
  void add(checker::Verdict verdict) {
    switch (verdict) {
    case checker::Verdict::holds:
      ++holds;
      break;
    case checker::Verdict::violated:
      ++violated;
      break;
    case checker::Verdict::incomplete:
      ++incomplete;
      break;
    }
  }
};

// 1 when something is violated, else 3 when something is incomplete, else 0.
inline int exit_status(const std::vector<checker::PropertyResult>& results) {
  bool incomplete = false;
  for (const auto& r : results) {
    if (r.verdict == checker::Verdict::violated)
      return some_violated;
    incomplete = incomplete || r.verdict == checker::Verdict::incomplete;
  }
  return incomplete ? some_incomplete : all_hold;
}

} // namespace cli
