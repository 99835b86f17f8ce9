#pragma once
// The motion-coordination algorithm at round level, over counts: the state is the number
// of robots assigned to each region at the start of a round (M_t); in round t every VN
// with robots runs assign (models/mc/assign.hpp) on the same snapshot M_t — the vn-update
// counts of the round, seed 002 §V-C / Fig. 6 — and all the reassignments take effect
// together: M_{t+1} = M_t − sent + received. No failures or recoveries happen from round
// t0 = 0 on (the setting of seed 002 §VI and seed 000 §6), so y_h(t) = M_t[h] for every
// VN that reads it.
//
// Robots' positions are not part of this level yet: a round is split into its plan (the
// Flow that assign produces from the counts) and its effect (Flow::apply), so that a
// later positional state can take the same plan and let calctarget move the robots.
//
// Sets of the analysis (seed 000 §6, seed 002 §VI), with "active" read at round level
// as "has at least one robot at the start of round t":
//   In(t)  = {h : M_t[h] >= 1, q_h != 0},   Out(t) = {h : M_t[h] >= 1, q_h = 0},
//   |C_in(t)| = Σ_{In(t)} M_t,  |C_out(t)| = Σ_{Out(t)} M_t; set claims about C_in/C_out
//   (which robots) are read from the Flow of the round.

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/mc/assign.hpp"
#include "models/mc/grid.hpp"
#include "models/mc/rational.hpp"

namespace mc {

using Counts = std::vector<RobotCount>; // robots per region, indexed by RegionId

// The parameters of VN(k, ρ1, ρ2) (seed 000 §5.4; e for k in seed 002): k ∈ Z⁺ and
// ρ1, ρ2 ∈ (0, 1). ρ1 is used by calctarget only (positions).
struct McParams {
  RobotCount k = 1;
  Rational rho1{1, 2};
  Rational rho2{9, 10};
};

struct Transfer {
  RegionId from;
  RegionId to;
  RobotCount robots; // > 0
  friend bool operator==(const Transfer&, const Transfer&) = default;
  friend auto operator<=>(const Transfer&, const Transfer&) = default;
};

// The flow matrix of one round, sparse: who sends how many robots to whom. Transfers are
// sorted by (from, to) and none is zero.
struct Flow {
  std::vector<Transfer> transfers;

  bool empty() const { return transfers.empty(); }
  RobotCount at(RegionId from, RegionId to) const;
  RobotCount sent_by(RegionId h) const;
  RobotCount received_by(RegionId h) const;
  // The counts after the round: counts − sent + received.
  Counts apply(const Counts& counts) const;
  // The dense matrix: row `from`, column `to`.
  std::vector<std::vector<RobotCount>> dense(std::size_t regions) const;

  friend bool operator==(const Flow&, const Flow&) = default;
  friend auto operator<=>(const Flow&, const Flow&) = default;
};

// run_to_fixpoint found no fixed point within the round limit.
class RoundLimitReached : public std::runtime_error {
public:
  RoundLimitReached(const std::string& what, std::size_t rounds)
      : std::runtime_error(what), rounds(rounds) {}
  std::size_t rounds;
};

// all_flows / all_next: more combinations of per-region outcomes than the limit allows.
class TooManyOutcomes : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::size_t max_rounds = 100'000; // the fixed point must be reached by round max_rounds
  bool keep_history = true;         // keep every M_t and every Flow (else only the last M)
  // Asked before each round when set: true gives up (RoundLimitReached, saying `stop_reason`)
  // — a time limit or an interrupt of the command line.
  std::function<bool()> stop = {};
  std::string stop_reason = "stopped";
};

// A run from M_0 to its fixed point M_F (the first round whose counts the next round
// leaves unchanged; then no robot moves any more: see models/mc/README.md).
struct FixpointRun {
  std::vector<Counts> rounds;     // M_0 .. M_F (keep_history), else {M_F}
  std::vector<Flow> flows;        // flows[t] takes M_t to M_{t+1}, t < F (keep_history)
  std::size_t fixpoint_round = 0; // F

  // T_out (seed 002 Lemma 3, seed 000 Lemma 6.5, fixed as "the first round after t0 at
  // which the property holds"): the first round t such that in every round t' >= t the
  // set of robots assigned to each VN_h, h ∈ Out(t'), is unchanged — no robot leaves or
  // joins an Out(t') region in round t'. 0 when that holds from the start. At round level
  // this is also the first round from which the count of every Out(t') region stays the
  // same (the first step of Lemma 3's proof): a robot leaving or joining an Out region
  // comes from an Out region, and the Out region with the most robots among those that
  // send receives none (transfers between Out regions go to fewer robots), so its count
  // drops.
  std::size_t t_out = 0;
  // T_stab (seed 002 Lemma 4, seed 000 Lemma 6.6): the first round t >= T_out such that in
  // every round t' >= t the set of robots of each VN_h, h ∈ In(t'), is unchanged. It
  // always equals F.
  std::size_t t_stab = 0;

  const Counts& fixpoint() const { return rounds.back(); }
};

class RoundSystem {
public:
  // q[u] = q_u in units of σ, indexed by RegionId. Throws std::invalid_argument on a size
  // that does not match the grid, q out of 0..max_quantised_length, or parameters out of
  // range (k >= 1, 0 < ρ1, ρ2 < 1).
  RoundSystem(GridTiling grid, std::vector<QuantisedLength> q, McParams params);

  const GridTiling& grid() const { return grid_; }
  const std::vector<QuantisedLength>& q() const { return q_; }
  const McParams& params() const { return params_; }
  const AssignParams& assign_params() const { return assign_params_; }
  bool on_curve(RegionId h) const { return q_[h] != 0; }

  // Throws std::invalid_argument unless counts has one entry per region, each >= 0, and
  // the total is at most max_robots.
  void check_counts(const Counts& counts) const;

  // What VN_h sees in a round that starts with `counts`.
  VnView view(const Counts& counts, RegionId h) const;

  // The flow of one round, every VN in the default order (lower by increasing id).
  Flow flow(const Counts& counts) const;
  // M_{t+1} from M_t, in the default order.
  Counts next(const Counts& counts) const;

  // Every flow of one round over all combinations of per-region outcomes of assign (over
  // all orders of each lower set): distinct, sorted. Throws TooManyOutcomes when the
  // number of combinations exceeds `limit`.
  std::vector<Flow> all_flows(const Counts& counts, std::size_t limit = 100'000) const;
  // The distinct successors of all_flows, sorted.
  std::vector<Counts> all_next(const Counts& counts, std::size_t limit = 100'000) const;

  std::vector<RegionId> in_regions(const Counts& counts) const;  // In(t)
  std::vector<RegionId> out_regions(const Counts& counts) const; // Out(t)

  // Rounds in the default order from `start` (round t0 = 0) until the counts stop
  // changing. Throws RoundLimitReached when they still change in round max_rounds.
  FixpointRun run_to_fixpoint(const Counts& start, const RunOptions& options = {}) const;

private:
  GridTiling grid_;
  std::vector<QuantisedLength> q_;
  McParams params_;
  AssignParams assign_params_;
};

RobotCount total(const Counts& counts);

} // namespace mc
