#include "checker/result.hpp"

namespace checker {

const char* to_string(Verdict verdict) {
  switch (verdict) {
  case Verdict::holds:
    return "holds";
  case Verdict::violated:
    return "violated";
  default:
    return "incomplete";
  }
}

PropertyResult result_of(const std::string& kind, const Exploration& ex,
                         const tioa::SuccessorGenerator& generator) {
  PropertyResult r;
  r.kind = kind;
  r.states = ex.store.size();
  r.edges = ex.edges;
  r.depth = ex.depth;
  r.seconds = ex.seconds;
  r.threads = ex.threads;
  r.por = ex.reduction;
  r.reduced_states = ex.reduced_states;
  r.time_unit = generator.timed() ? "quanta" : "steps";
  return r;
}

void mark_incomplete(PropertyResult& result, const Exploration& ex, const std::string& covered) {
  result.verdict = Verdict::incomplete;
  result.message = std::string(describe(ex.stop)) + " after " + std::to_string(ex.store.size()) +
                   " states to depth " + std::to_string(ex.depth) + ": " + covered;
}

} // namespace checker
