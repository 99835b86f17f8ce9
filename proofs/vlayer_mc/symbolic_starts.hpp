#pragma once
// Stabilisation from every start state of U(VLNodes) ‖ R(RW ‖ VW ‖ VBcast) at once,
// symbolically (checker/symbolic_stabilisation.hpp): R(env) is computed as a BDD from the
// environment's start states, the nodes' variables range over every valuation, and the legal
// sets are built conjunct by conjunct. On 1x1 with one robot and no junk slots that is
// 1.1·10^16 start states, each check decided in under two minutes.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/options.hpp"
#include "checker/progress.hpp"
#include "checker/symbolic_stabilisation.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "proofs/vlayer_mc/arbitrary_starts.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"

namespace vlayer_mc {

// SymbolicU::without_junk() in words, for reports.
inline const std::string without_junk_words = "the start states whose junk slots are empty";

struct SymbolicRun {
  checker::symbolic::StabilisationResult result;
  double environment_states = 0; // |R(env)|
  std::uint64_t learned_cubes = 0;
  double seconds = 0;     // since the SymbolicU was made: learning and R(env) included
  std::string stopped_by; // "the time limit" or "the memory limit", when result.stopped
};

// The layer's steps learned and its start states U(VLNodes) ‖ R(env) as one set, for one or
// more stabilisation checks on the same layer. Holds the one BddSession.
class SymbolicU {
public:
  // `layer` is u_layer(config, starts). R(env) may stop at the options' limits of time or
  // memory (resident memory, asked before every step group of a fixpoint round):
  // stopped(). With options.progress, each group redraws a progress line on a terminal.
  SymbolicU(const VlConfig& config, const ArbitraryStarts& starts, const tioa::Automaton& layer,
            const checker::ExploreOptions& options);

  bool stopped() const { return !system_; } // R(env) was not finished
  const checker::symbolic::Space& space() const { return *space_; }
  const bdd& start() const { return start_; }
  // The start states whose junk slots (D31) are all empty (every field 0): the start
  // states of the same instance with `junk=0`, inside this layer (no step fills a junk
  // slot). Equal to start() when the layer has no junk slots.
  const bdd& without_junk() const { return without_junk_; }
  double environment_states() const { return environment_states_; }

  // When stopped(), the sets below are empty and stabilise() says stopped.

  // The states that satisfy every one of `conjuncts`.
  bdd conjunction(const std::vector<tioa::StatePredicate>& conjuncts);
  // "In LMC" as Lemma 7.4 and Theorem 7.5 measure it (in_measured_lmc): ResetMC or D30's
  // exception, or a state KnownLmc::contains (symbolic_lmc.hpp). `layer` is the one given.
  bdd measured_lmc(const VlConfig& config, const tioa::Automaton& layer, MWindow window,
                   const KnownLmc& known);

  // From `start` into `legal`, with `settled` counted in L and not expanded (bddfalse: none);
  // a start state of a worst case is picked when the worst time exceeds `witness_after`.
  // `part` names the part of the start set `start` is, for the progress line ("without
  // junk: time layer 3: ..."). `apart`: in a child process (checker/symbolic_apart.hpp),
  // so that the time limit or an interrupt ends it at once, not after the image being
  // computed; for a run whose result may be given up (what the child reorders is lost).
  SymbolicRun stabilise(const bdd& start, const bdd& legal, const bdd& settled,
                        std::uint64_t witness_after, const std::string& part = "",
                        bool apart = false);

private:
  double elapsed() const;
  // Whether to stop (an interrupt, the time limit, the memory limit: stopped_by_ says which).
  bool should_stop();

  std::chrono::steady_clock::time_point began_;
  checker::Limits limits_;
  checker::Progress progress_; // (before system_, whose rounds report to it)
  tioa::Automaton environment_;
  std::unique_ptr<checker::symbolic::BddSession> session_; // (every bdd below goes first)
  checker::symbolic::LearningFigures figures_;
  std::optional<checker::symbolic::Space> space_;
  std::optional<checker::symbolic::System> system_;
  bdd start_ = bddfalse, without_junk_ = bddfalse;
  double environment_states_ = 0;
  std::string stopped_by_;
  std::string part_; // what the progress line says first ("without junk: ")
};

} // namespace vlayer_mc
