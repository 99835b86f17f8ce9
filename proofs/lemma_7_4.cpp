#include "proofs/lemma_7_4.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "checker/checks.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "proofs/vlayer_mc/legal_sets.hpp"
#include "proofs/vlayer_mc/stabilisation_common.hpp"
#include "proofs/vlayer_mc/symbolic_starts.hpp"
#include "proofs/vlayer_mc/symbolic_verdict.hpp"
#include "tioa/operators.hpp"

namespace vlayer_mc {

namespace {

using checker::PropertyResult;

// The robots at their start points, nothing failed: the instance of the other properties.
tioa::Automaton placed_instance(const VlConfig& c, const tioa::Automaton& layer) {
  return tioa::Start(layer, placed_start(layer, start_points(c)));
}

// The figures and notes every Lemma 7.4 result carries.
PropertyResult finish_7_4(PropertyResult r, const VlConfig& c, const ArbitraryStarts& starts,
                          const tioa::Automaton& layer, const KnownLmc& known) {
  r.figures.emplace_back("known LMC", describe_known(known));
  r.notes.push_back(lmc_measure_note);
  return with_common_notes(std::move(r), c, starts, layer);
}

// From every L1MC state at once (symbolic_verdict.hpp): L1MC is every start state of
// U(VLNodes) || R(env) in it.
PropertyResult lemma_7_4_symbolically(const VlConfig& c, MWindow window,
                                      const ArbitraryStarts& starts,
                                      const checker::ExploreOptions& options) {
  const tioa::Automaton layer = u_layer(c, starts);
  const KnownLmc known(c, layer, options);
  const tioa::StatePredicate in_lmc = in_measured_lmc(c, layer, window, known);
  const std::uint64_t bound = static_cast<std::uint64_t>(c.delta + c.d + c.e);
  SymbolicU u(c, starts, layer, options);
  const bdd lmc = u.measured_lmc(c, layer, window, known);
  const bdd l1 = u.start() & u.conjunction(l1mc_conjuncts(c, layer, window));
  const SymbolicClaim claim{"Lemma 7.4 (from L1MC, in LMC from delta + d + e on)",
                            bound,
                            false,
                            known.complete(),
                            "L1MC (Def 7.1)",
                            in_lmc,
                            in_lmc,
                            {}};
  // Counterexample first, as Lemma 7.3 (lemma_7_3.cpp).
  std::optional<PropertyResult> from_part;
  if (u.without_junk() != u.start())
    from_part =
        judge_symbolic_part(u.stabilise(l1 & u.without_junk(), lmc, lmc, bound, "without junk"),
                            u.space().count(l1), without_junk_words, layer, claim, options);
  const SymbolicRun run = u.stabilise(l1, lmc, lmc, bound, "", from_part.has_value());
  if (run.result.stopped && from_part)
    return finish_7_4(part_when_whole_stopped(std::move(*from_part), run), c, starts, layer, known);
  return finish_7_4(judge_symbolic(run, layer, claim, options), c, starts, layer, known);
}

} // namespace

PropertyResult check_lemma_7_4(const VlConfig& c, MWindow window, const ArbitraryStarts& starts,
                               const checker::ExploreOptions& options) {
  if (starts.symbolic)
    return lemma_7_4_symbolically(c, window, starts, options);
  const UStarts u = u_starts(c, starts, options);
  const tioa::StatePredicate in_l1mc = l1mc(c, u.layer, window);
  bool complete = true;
  StateList from = reached_where(placed_instance(c, u.layer), in_l1mc, options, complete);
  const std::size_t from_instance = from.size();
  const StateList arbitrary =
      reached_where(tioa::Start(u.layer, u.states.start(u.layer, "U(VLNodes) || R(env)")), in_l1mc,
                    options, complete);
  from.data.insert(from.data.end(), arbitrary.data.begin(), arbitrary.data.end());
  const KnownLmc known(c, u.layer, options);
  complete = complete && known.complete();
  const tioa::StatePredicate in_lmc = in_measured_lmc(c, u.layer, window, known);
  PropertyResult m = checker::check_stabilisation(
      tioa::Start(u.layer, from.start(u.layer, "L1MC states reached")), in_lmc, in_lmc, options);
  // Every L1MC state is a start state of U(VLNodes) || R(env) (its environment part is
  // reachable, Def 7.1(1)), so the L1MC states reached cover all of L1MC only when all of
  // U(VLNodes) || R(env) was explored; a sample covers the L1MC states it reaches.
  PropertyResult r = judge(std::move(m), static_cast<std::uint64_t>(c.delta + c.d + c.e),
                           "Lemma 7.4 (from L1MC, in LMC from delta + d + e on)",
                           u.exhaustive && complete, false, "");
  const bool all = u.exhaustive && complete;
  const std::uint64_t covered = r.coverage.count; // distinct start states of the measurement
  r.coverage = {all ? checker::Starts::all : checker::Starts::sampled, covered, std::nullopt,
                "L1MC (Def 7.1)",
                all ? ""
                    : "the L1MC states reached from the instance's start state and from " +
                          std::to_string(u.coverage.count) +
                          " start states of U(VLNodes) || R(env), " + u.coverage.chosen};
  if (all)
    r.coverage.of = covered;
  r.figures.emplace_back(
      "covered", "the " + std::to_string(from_instance) + " L1MC states reachable from " +
                     placed_instance(c, u.layer).start().description() + " and the " +
                     std::to_string(arbitrary.size()) + " L1MC states reached from " + u.covered +
                     " (duplicates counted once by the exploration), not all of L1MC: its " +
                     "valuations are too many to enumerate");
  return finish_7_4(std::move(r), c, starts, u.layer, known);
}

} // namespace vlayer_mc
