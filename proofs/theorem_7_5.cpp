#include "proofs/theorem_7_5.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "checker/checks.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "proofs/vlayer_mc/stabilisation_common.hpp"
#include "proofs/vlayer_mc/symbolic_starts.hpp"
#include "proofs/vlayer_mc/symbolic_verdict.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;
using checker::Verdict;

// The three measurements of Theorem 7.5: start -> L1MC (t1), L1MC -> LMC (t2), start -> LMC
// (t, judged), each a worst time or (none) a verdict.
struct Times {
  std::optional<std::uint64_t> t1, t2;
  std::string t1_text, t2_text;
};

std::string time_of(const std::optional<std::uint64_t>& worst, Verdict verdict) {
  return worst ? std::to_string(*worst) : std::string(checker::to_string(verdict));
}

// Lemma 3.4's composition (t <= t1 + t2), the three figures, and the notes every Theorem
// 7.5 result carries.
PropertyResult finish_7_5(PropertyResult r, const Times& times, const VlConfig& c,
                          const ArbitraryStarts& starts, const tioa::Automaton& layer,
                          const KnownLmc& known) {
  const std::string t = time_of(r.worst_time, r.verdict);
  r.figures.emplace_back("t1 (start -> L1MC, Lemma 7.3)", times.t1_text);
  r.figures.emplace_back("t2 (L1MC -> LMC, Lemma 7.4)", times.t2_text);
  r.figures.emplace_back("t (start -> LMC, direct)", t);
  if (times.t1 && times.t2 && r.worst_time && *r.worst_time > *times.t1 + *times.t2) {
    r.verdict = Verdict::violated;
    r.message = "Lemma 3.4 fails: start -> LMC takes " + t +
                " but t1 + t2 = " + std::to_string(*times.t1 + *times.t2);
  } else if (times.t1 && times.t2) {
    r.notes.push_back("Lemma 3.4: t = " + t +
                      " <= t1 + t2 = " + std::to_string(*times.t1 + *times.t2));
  }
  r.figures.emplace_back("known LMC", describe_known(known));
  r.notes.push_back(lmc_measure_note);
  return with_common_notes(std::move(r), c, starts, layer);
}

// Every start state at once (symbolic_verdict.hpp): t1 and t2 from every start state and
// every L1MC state, t judged.
PropertyResult theorem_7_5_symbolically(const VlConfig& c, MWindow window,
                                        const ArbitraryStarts& starts,
                                        const checker::ExploreOptions& options) {
  const tioa::Automaton layer = u_layer(c, starts);
  const KnownLmc known(c, layer, options);
  const tioa::StatePredicate in_lmc = in_measured_lmc(c, layer, window, known);
  const std::uint64_t bound = static_cast<std::uint64_t>(c.delta + c.d + c.e + c.eps_sample);
  const std::uint64_t no_witness = std::numeric_limits<std::uint64_t>::max();
  SymbolicU u(c, starts, layer, options);
  const bdd l1 = u.conjunction(l1mc_conjuncts(c, layer, window));
  const bdd lmc = u.measured_lmc(c, layer, window, known);
  const auto text = [](const SymbolicRun& run) {
    return run.result.stopped ? std::string("stopped")
                              : time_of(run.result.worst, Verdict::incomplete);
  };
  Times times;
  const SymbolicRun first = u.stabilise(u.start(), l1, bddfalse, no_witness);
  times.t1 = first.result.worst;
  times.t1_text = text(first);
  const SymbolicRun second = u.stabilise(u.start() & l1, lmc, lmc, no_witness);
  times.t2 = second.result.worst;
  times.t2_text = text(second);
  const SymbolicRun direct = u.stabilise(u.start(), lmc, lmc, bound);
  const SymbolicClaim claim{"Theorem 7.5 (in LMC from delta + d + e + eps_sample on)",
                            bound,
                            false,
                            known.complete(),
                            u_layer_name,
                            in_lmc,
                            in_lmc,
                            {}};
  PropertyResult r = judge_symbolic(direct, layer, claim, options);
  r.notes.push_back("t1 and t2 are worst times from every start state and from every L1MC "
                    "state (Lemmas 7.3 and 7.4), decided symbolically" +
                    std::string(first.result.worst ? "" : "; t1 none: outside L1MC for ever") +
                    std::string(second.result.worst ? "" : "; t2 none: outside LMC for ever"));
  return finish_7_5(std::move(r), times, c, starts, layer, known);
}

} // namespace

PropertyResult check_theorem_7_5(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                                 const checker::ExploreOptions& options) {
  if (starts.symbolic)
    return theorem_7_5_symbolically(c, window, starts, options);
  const UStarts u = u_starts(c, starts, options);
  const tioa::Automaton system =
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)"));
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  const KnownLmc known(c, u.layer, options);
  const tioa::StatePredicate in_lmc = in_measured_lmc(c, u.layer, window, known);

  const PropertyResult first = checker::check_stabilisation(system, in_l1mc, options);
  bool complete = true;
  const StateList reached = reached_where(system, in_l1mc, options, complete);
  const PropertyResult second = checker::check_stabilisation(
      tioa::Start(u.layer, reached.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  PropertyResult direct = checker::check_stabilisation(system, in_lmc, in_lmc, options);

  const std::uint64_t bound = static_cast<std::uint64_t>(c.delta + c.d + c.e + c.eps_sample);
  PropertyResult r = judge(direct, bound, "Theorem 7.5 (in LMC from delta + d + e + eps_sample on)",
                           u.exhaustive && complete && known.complete(), false, "");
  r.figures.emplace_back("covered", u.covered);
  r.coverage = u.coverage;
  r.states = first.states + second.states + direct.states;
  r.edges = first.edges + second.edges + direct.edges;
  r.seconds = first.seconds + second.seconds + direct.seconds;
  const Times times{first.worst_time, second.worst_time, time_of(first.worst_time, first.verdict),
                    time_of(second.worst_time, second.verdict)};
  return finish_7_5(std::move(r), times, c, starts, u.layer, known);
}

} // namespace vlayer_mc
