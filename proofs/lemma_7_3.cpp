#include "proofs/lemma_7_3.hpp"

#include <cstdint>
#include <optional>
#include <string>

#include "checker/checks.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "proofs/vlayer_mc/stabilisation_common.hpp"
#include "proofs/vlayer_mc/symbolic_starts.hpp"
#include "proofs/vlayer_mc/symbolic_verdict.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;

// The clauses of `clauses` that the last state of the trace outside `legal` breaks.
std::string last_outside(const PropertyResult& r, const tioa::StatePredicate& legal,
                         const ClauseCheck& clauses) {
  if (!r.trace)
    return "";
  for (auto it = r.trace->steps.rbegin(); it != r.trace->steps.rend(); ++it) {
    const tioa::State s(it->state.data(), 0);
    if (!legal(s)) {
      std::string broken;
      for (const auto& clause : clauses(s))
        broken += (broken.empty() ? "" : ", ") + clause;
      return "the last state outside, at time " + std::to_string(it->time) + " after " +
             (it->action.empty() ? std::string("the start") : it->action) + ", breaks " + broken;
    }
  }
  return "";
}

// The notes and trace system every Lemma 7.3 result carries.
PropertyResult finish(PropertyResult r, const VlConfig& c, const ArbitraryStarts& starts,
                      const tioa::Automaton& layer) {
  r.notes.push_back("the bound: time t > eps_sample = " + std::to_string(c.eps_sample) +
                    " is, in whole quanta, t = eps_sample + 1");
  return with_common_notes(std::move(r), c, starts, layer);
}

// Every start state at once (symbolic_verdict.hpp).
PropertyResult lemma_7_3_symbolically(const VlConfig& c, MWindow window,
                                      const ArbitraryStarts& starts,
                                      const checker::ExploreOptions& options) {
  const tioa::Automaton layer = u_layer(c, starts);
  const tioa::StatePredicate legal = l1mc(c, layer, window);
  const ClauseCheck clauses = l1mc_clauses(c, layer, window);
  const std::uint64_t bound = static_cast<std::uint64_t>(c.eps_sample) + 1;
  SymbolicU u(c, starts, layer, options);
  const bdd in_l1mc = u.conjunction(l1mc_conjuncts(c, layer, window));
  const SymbolicClaim claim{
      "Lemma 7.3 (in L1MC from any t > eps_sample on)",
      bound,
      true,
      true,
      u_layer_name,
      legal,
      {},
      [&](const PropertyResult& m) { return last_outside(m, legal, clauses); }};
  // Counterexample first (symbolic_verdict.hpp): the start states without junk are far
  // cheaper than all of them (on 1x2 the whole set's first time layer passes 100 M BDD
  // nodes, README "Not done"), and a worst time past the bound there decides the verdict.
  // The whole set still follows, for its exact worst time; when it stops (a limit, an
  // interrupt), the part's verdict is the result.
  std::optional<PropertyResult> from_part;
  if (u.without_junk() != u.start())
    from_part =
        judge_symbolic_part(u.stabilise(u.without_junk(), in_l1mc, bddfalse, bound, "without junk"),
                            u.space().count(u.start()), without_junk_words, layer, claim, options);
  // (In a child process once the part has a verdict, so that a stop gives it at once.)
  const SymbolicRun run =
      u.stabilise(u.start(), in_l1mc, bddfalse, bound, "", from_part.has_value());
  if (run.result.stopped && from_part)
    return finish(part_when_whole_stopped(std::move(*from_part), run), c, starts, layer);
  return finish(judge_symbolic(run, layer, claim, options), c, starts, layer);
}

} // namespace

PropertyResult check_lemma_7_3(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  if (starts.symbolic)
    return lemma_7_3_symbolically(c, window, starts, options);
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate legal = l1mc(c, u.layer, window);
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(RW || VW || VBcast)")), legal,
      options);
  const std::string detail = last_outside(m, legal, l1mc_clauses(c, u.layer, window));
  PropertyResult r =
      judge(std::move(m), static_cast<std::uint64_t>(c.eps_sample) + 1,
            "Lemma 7.3 (in L1MC from any t > eps_sample on)", u.exhaustive, true, detail);
  r.figures.emplace_back("covered", u.covered);
  r.coverage = u.coverage;
  return finish(std::move(r), c, starts, u.layer);
}

} // namespace vlayer_mc
