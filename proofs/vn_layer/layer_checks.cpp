#include "proofs/vn_layer/layer_checks.hpp"

#include <memory>

#include "checker/property.hpp"
#include "models/vn_layer/observers.hpp"
#include "proofs/vn_layer/round_timing_figures.hpp"

namespace vn_layer {

namespace {

using Failure = std::optional<std::string> (Observers::*)(const tioa::State&) const;

// check_invariant of "no failure", within the model's bounds (an overflow makes the check
// incomplete, checker::Property::beyond_bound), with the failure of the trace's last state.
checker::PropertyResult check_observed(const VnConfig& c, const tioa::Automaton& system,
                                       const checker::ExploreOptions& options, Failure failure,
                                       std::string name, std::string description) {
  const auto observers = std::make_shared<const Observers>(system, c);
  checker::Property property;
  property.name = name;
  property.description = description;
  property.kind = checker::PropertyKind::invariant;
  property.predicate = [=](const tioa::State& s) { return !((*observers).*failure)(s); };
  property.predicate_name = std::move(description);
  property.beyond_bound = [=](const tioa::State& s) { return observers->overflowed(s); };
  property.bound_name = "a send-buffer of 2 messages, or one message per kind and sender in "
                        "VLBcast";
  checker::PropertyResult r = checker::run_property(system, property, options);
  if (r.verdict == checker::Verdict::violated && r.trace && !r.trace->steps.empty()) {
    std::vector<tioa::Word> last = r.trace->steps.back().state;
    last.push_back(0);
    if (const auto why = ((*observers).*failure)(tioa::State(last.data(), 0)))
      r.notes.push_back("the last state breaks " + *why);
  }
  note_round_rules(c, r);
  return r;
}

} // namespace

checker::PropertyResult check_round_timing(const VnConfig& c, const tioa::Automaton& system,
                                           const checker::ExploreOptions& options) {
  checker::PropertyResult r =
      check_observed(c, system, options, &Observers::round_timing_failure, "round-timing",
                     "(T1)-(T4) of seed 002 §V-B: messages within their slots, CNs on "
                     "target and VNs alive at every round start");
  // The figures need every step of every reachable state: only a run that held saw them.
  if (r.verdict == checker::Verdict::holds)
    add_round_timing_figures(c, system, options, r);
  return r;
}

checker::PropertyResult check_y_consistency(const VnConfig& c, const tioa::Automaton& system,
                                            const checker::ExploreOptions& options) {
  return check_observed(c, system, options, &Observers::y_failure, "y-consistency",
                        "VNs that compute in the same round agree on every count they share "
                        "(seed 002 §VI, line 232)");
}

checker::PropertyResult check_cn_reports(const VnConfig& c, const tioa::Automaton& system,
                                         const checker::ExploreOptions& options) {
  checker::PropertyResult r = check_observed(
      c, system, options, &Observers::silent_cn, "cn-reports",
      "no active CN holds a round counter in a past round, so every active CN reports and "
      "triggers in every round (the premise of Theorem 1(2), seed 001 / 002 §VI)");
  if (c.cn_fail == CnFail::keep)
    r.notes.push_back("cn_fail=keep: a failing CN keeps its variables (seed 001 line 36); "
                      "seed 002 line 35 resets them, which the default cn_fail=reset follows");
  return r;
}

void note_round_rules(const VnConfig& c, checker::PropertyResult& r) {
  const std::string paper = c.paper_round_bound_text();
  const int lattice = lattice_round_bound(c);
  const bool paper_ok = paper_round_rule_holds(c), lattice_ok = c.delta > lattice;
  r.notes.push_back("delta = " + std::to_string(c.delta) + (paper_ok ? " meets" : " breaks") +
                    " the paper's round-length rule (seed 002 §V-B: delta > " + paper + ") and" +
                    (lattice_ok ? " meets" : " breaks") + " the lattice's (delta > " +
                    std::to_string(lattice) + ", models/vn_layer/README.md)");
}

} // namespace vn_layer
