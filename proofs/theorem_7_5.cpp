#include "proofs/theorem_7_5.hpp"

#include <cstdint>
#include <memory>
#include <string>

#include "checker/checks.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "proofs/vlayer_mc/stabilisation_common.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;

} // namespace

PropertyResult check_theorem_7_5(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                                 const checker::ExploreOptions& options) {
  const UStarts u = u_starts(c, starts, options);
  const tioa::Automaton system =
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)"));
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  const tioa::StatePredicate reset = reset_mc_or_targetless(c, u.layer, window);
  const KnownLmc known(c, u.layer, options);
  const tioa::StatePredicate in_lmc = [&](const tioa::State& s) {
    return reset(s) || known.contains(s);
  };

  const PropertyResult first = checker::check_stabilisation(system, in_l1mc, options);
  bool complete = true;
  const StateList reached = reached_where(system, in_l1mc, options, complete);
  const PropertyResult second = checker::check_stabilisation(
      tioa::Start(u.layer, reached.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  PropertyResult direct = checker::check_stabilisation(system, in_lmc, in_lmc, options);

  const std::uint64_t bound = static_cast<std::uint64_t>(c.delta + c.d + c.e + c.eps_sample);
  PropertyResult r = judge(direct, bound, "Theorem 7.5 (in LMC from delta + d + e + eps_sample on)",
                           u.exhaustive && complete && known.complete(), false, "");
  const auto time_of = [](const PropertyResult& p) {
    return p.worst_time ? std::to_string(*p.worst_time)
                        : std::string(checker::to_string(p.verdict));
  };
  r.figures.emplace_back("t1 (start -> L1MC, Lemma 7.3)", time_of(first));
  r.figures.emplace_back("t2 (L1MC -> LMC, Lemma 7.4)", time_of(second));
  r.figures.emplace_back("t (start -> LMC, direct)", time_of(direct));
  r.figures.emplace_back("covered", u.covered);
  r.coverage = u.coverage;
  if (first.worst_time && second.worst_time && direct.worst_time &&
      *direct.worst_time > *first.worst_time + *second.worst_time) {
    r.verdict = Verdict::violated;
    r.message = "Lemma 3.4 fails: start -> LMC takes " + time_of(direct) +
                " but t1 + t2 = " + std::to_string(*first.worst_time + *second.worst_time);
  } else if (first.worst_time && second.worst_time) {
    r.notes.push_back("Lemma 3.4: t = " + time_of(direct) +
                      " <= t1 + t2 = " + std::to_string(*first.worst_time + *second.worst_time));
  }
  r.states = first.states + second.states + direct.states;
  r.edges = first.edges + second.edges + direct.edges;
  r.seconds = first.seconds + second.seconds + direct.seconds;
  r.figures.emplace_back("known LMC", describe_known(known));
  r.notes.push_back(lmc_measure_note);
  r.notes.push_back(faults_note(starts.faults, c.dr_rule));
  r.notes.push_back(junk_note(starts.junk));
  if (starts.symbolic)
    r.notes.push_back("starts=all decides lemma-7.3 only (symbolically); this property drew "
                      "its start states as with starts=sampled");
  // Its trace is one of u.layer, which has junk slots (D31).
  r.trace_system = std::make_shared<const tioa::Automaton>(u.layer);
  r.trace_system_name = u_layer_name;
  note_repairs(c, r);
  note_round_length(c, r);
  return r;
}

} // namespace vlayer_mc
