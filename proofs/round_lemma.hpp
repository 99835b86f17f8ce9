#pragma once
// What the one-step lemmas (6.1, 6.4) share: a lemma is a list of claims about one round
// t -> t+1 of the round-level system (models/mc/round.hpp) and a function that evaluates
// them on one outcome of the round. This file runs such a lemma
//
//   - exhaustively over a Family (proofs/family.hpp): every instance, every outcome of
//     RoundSystem::all_flows (every order of every lower set), and keeps for each claim the
//     smallest counterexample (fewest robots, then smallest grid, then the first in
//     enumeration order);
//   - as a seeded random search over larger instances, with every counterexample it finds
//     shrunk (smaller grid, fewer robots, smaller k and q) to a small one;
//
// and turns the outcome into a checker::PropertyResult (name, kind "round-lemma", verdict,
// states = instances, edges = (instance, outcome) pairs, figures, notes) with the
// counterexample printed line by line in `notes`.
//
// Claims of two kinds: the lemma's statements (conference and journal, which differ), which
// decide the verdict, and steps of the paper's proof, reported beside them so that a
// failing statement shows which step breaks (they do not decide the verdict).

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>
#include <vector>

#include "checker/options.hpp"
#include "checker/result.hpp"
#include "models/mc/round.hpp"
#include "proofs/claim_tally.hpp"
#include "proofs/family.hpp"
#include "proofs/family_stop.hpp"
#include "proofs/split_mix64.hpp"

namespace proofs {

// One round t -> t+1: the counts at t, one outcome of the round, the counts at t+1.
struct RoundStep {
  const mc::RoundSystem& system;
  const Counts& before; // M_t
  const mc::Flow& flow; // one element of all_flows(M_t)
  const Counts& after;  // M_{t+1} = flow.apply(M_t)
};

// A claim of a one-step lemma: id ("6.1(1)", "L2(2)", "L2(2) step: ..."), statement, source
// ("seed 000 line 1044; seed 002 line 246"), whether it decides the verdict.
struct Claim : ClaimStatement {
  // Only rounds inside the journal's window t ∈ [t2, …] (seed 000 Lemmas 6.2, 6.3): a
  // failure counts when RoundLemma::confirm_window places the round in such a window.
  bool journal_window = false;
};

// One claim on one round.
struct ClaimOutcome {
  std::uint64_t premise = 0;          // how many times its premise was met (regions, pairs)
  std::optional<std::string> failure; // why it fails, in one line (the first failure)
};

struct RoundLemma {
  std::string name;        // "lemma-6.1"
  std::string description; // one line
  std::vector<Claim> claims;
  // Fills out[i] for claims[i]; out has claims.size() elements, reset by the caller.
  std::function<void(const RoundStep&, std::vector<ClaimOutcome>& out)> evaluate;
  // For journal_window claims: nullopt when the round is shown to lie in a window, else
  // why not. Needed only when some claim has journal_window.
  std::function<std::optional<std::string>(const RoundStep&)> confirm_window;
};

// A violation of one claim in one round, printable.
struct RoundCounterexample {
  std::string claim; // Claim::id
  Setting setting;
  Counts before;
  mc::Flow flow;
  Counts after;
  std::string why;

  RobotCount robots() const { return mc::total(before); }
  // Fewest robots, then the smaller grid.
  std::tuple<RobotCount, int> order_key() const { return {robots(), setting.m}; }
  // The instance, the counts at t, the flow, the counts at t+1 and why the claim fails.
  std::vector<std::string> lines() const;
  // The same as a JSON object (proofs/witness_json.hpp), as text.
  std::string json() const;
};

// A claim of a one-step lemma over a check: premise met, violations (instance, outcome pairs),
// both weighted by orbit size too, `undecided` the failures of a journal_window claim on
// rounds not shown to lie in a window (not violations), the smallest counterexample.
// verdict(): violated, else incomplete when undecided, else holds.
using ClaimTally = Tally<RoundCounterexample>;
// "holds; premise met 123 times", "violated in 4 (instance, outcome) pairs; …"
template <> std::string Tally<RoundCounterexample>::summary() const;

struct LemmaCheck : Check<RoundCounterexample> {
  std::uint64_t instances = 0;            // instances checked
  std::uint64_t skipped = 0;              // symmetric duplicates skipped
  std::uint64_t represented = 0;          // configurations of the unreduced family
  std::uint64_t outcomes = 0;             // (instance, outcome) pairs checked
  std::uint64_t outcomes_represented = 0; // weighted by orbit size
  std::uint64_t sampled_outcome_instances =
      0; // random search: instances whose outcomes were sampled
  // `counterexample`: the smallest over the claims that decide the verdict.
};

// Runs `work` on `threads` threads (this one included) and waits for all of them; the
// checks split their settings between threads through a shared counter inside `work`.
template <class Work> void run_on_threads(unsigned threads, Work& work) {
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::max(1u, threads); ++t)
    pool.emplace_back([&work] { work(); });
  work();
  for (auto& t : pool)
    t.join();
}

struct CheckOptions {
  unsigned threads = 1;                // settings are split between threads; same results
  std::size_t outcome_limit = 100'000; // all_flows limit per instance
  // The property's limits (each instance one state); none: the whole family (family_stop.hpp).
  const checker::Limits* limits = nullptr;
};

// Every instance of the family, every outcome of its round.
LemmaCheck check_family(const RoundLemma& lemma, const Family& family,
                        const CheckOptions& options = {});

struct SearchOptions {
  std::uint64_t seed = 1;
  std::uint64_t samples = 20'000;
  mc::Neighbourhood neighbourhood = mc::Neighbourhood::four;
  int min_side = 2;
  int max_side = 5;
  RobotCount max_count = 500; // a region holds 0..max_count robots (see README for the mix)
  std::vector<RobotCount> ks{1, 2, 3};
  std::vector<mc::Rational> rho2s{{1, 2}, {9, 10}, {1, 10}, {2, 3}};
  // Curves: a third of the samples a random grid path (proofs/random_curve.hpp), the rest a
  // named curve or "random" (each region off the curve or q in 1..3); grid_paths = false
  // leaves the paths out. given_curve: every sample on that curve, m its side.
  bool grid_paths = true;
  std::optional<GivenCurve> given_curve;
  // More combinations of per-region outcomes than this: check `sampled_outcomes` of them,
  // drawn from the seeded generator, and the default order.
  std::size_t outcome_limit = 4'096;
  std::size_t sampled_outcomes = 64;
  bool shrink = true;
  const checker::Limits* limits = nullptr; // the property's limits (family_stop.hpp)
};

// A seeded random search; its verdict is never a plain "holds" (see README).
LemmaCheck search_random(const RoundLemma& lemma, const SearchOptions& options);

// The first outcome of the instance's round on which claims[claim] fails (for a
// journal_window claim: a failure inside a confirmed window), in all_flows order; when there
// are more than outcome_limit outcomes, `sampled` of them from a fixed seed, and the default.
std::optional<RoundCounterexample> find_violation(const RoundLemma& lemma, std::size_t claim,
                                                  const Instance& instance,
                                                  std::size_t outcome_limit = 4'096,
                                                  std::size_t sampled = 64);

// Shrinks a counterexample of claims[claim] while it stays one, greedily, until nothing
// shrinks: remove a row and a column; scale every count down together; lower a group of
// counts (all, those on the curve, those off it) by the same amount; lower the regions of
// one count together; lower each count alone (to 0, then by halves, then by 1); lower k;
// lower each q (to 0, then by 1). Deterministic.
// The shrinker both searches use (this one and proofs/fixpoint_search.hpp): greedily, while
// `fails` still holds of the smaller instance, until nothing shrinks — remove a row and a
// column; scale every count down together; lower every region with robots (or those on /
// off the curve) by the same number; lower a plateau of equal counts, then each region
// alone; a smaller k; a smaller q. Returns the last instance `fails` accepted (`start` if
// none), its curve renamed "shrunk from …" when q or m changed.
Instance shrink_instance(const Instance& start, const std::function<bool(const Instance&)>& fails);

RoundCounterexample shrink(const RoundLemma& lemma, std::size_t claim,
                           const RoundCounterexample& start, std::size_t outcome_limit = 4'096,
                           std::size_t sampled = 64);

} // namespace proofs
