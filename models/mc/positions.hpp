#pragma once
// The motion-coordination algorithm at round level with robots' positions (seed 002 §V,
// Figs. 5–7; seed 000 §5): the state is the robots, each with an id and an exact
// position. One round:
//
//   a. membership: the VN each robot reports to (its cn-update, seed 002 line 111: "the
//      VN in whose zone the CN currently resides"), read one of two ways (Membership);
//      the counts per region follow;
//   b. assign: the Flow of RoundSystem on those counts (default order; q from the curve);
//   c. which robots each VN_h reassigns (line 11 "reassigning ra nodes from h to g" does
//      not say): a rule (Reassignment);
//   d. calctarget (Fig. 7 lines 26–38) per VN_h, exactly (models/mc/exact_local_curve.hpp);
//   e. every robot reaches its target within the round (the round length δ is chosen
//      so, seed 002 §V-B).
//
// A robot sent by VN_h to an end of Γ_h that the next region owns (line 35 with
// inf_owned false, line 36 with sup_owned false) then stands in that region; under
// Membership::position it reports to that region's VN next round, a move assign did not
// make. Such moves are recorded as migrations (models/mc/README.md, "Positions and
// calctarget": they can keep the assignment from ever becoming fixed).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/mc/exact_local_curve.hpp"
#include "models/mc/round.hpp"

namespace mc {

using RobotId = std::uint32_t;

struct Robot {
  RobotId id = 0;
  RationalPoint position;
  // The VN that assigned it in the last round (assign's output: the region it stays in
  // or is reassigned to); none before the first round.
  std::optional<RegionId> assigned;
  friend bool operator==(const Robot&, const Robot&) = default;
};

// Which VN a robot reports to at the start of a round.
enum class Membership {
  // The region that owns its position (seed 002 line 111; the ownership rule of
  // CurveOnGrid). The faithful reading.
  position,
  // The region it was last assigned to, while it stands in the closed square of that
  // region (seed 000 §4.1: regions are closed); by position otherwise and initially. The
  // reading under which the proof of seed 002 Lemma 7 works.
  assigned,
};

// Which of VN_h's robots line 11 reassigns. Either way only positions depend on it.
enum class Reassignment {
  lowest_ids, // the robots of h by increasing id: the first ra to the first g of the flow, …
  random,     // a shuffle of them, reproducible from (seed, round, h)
};

struct PositionOptions {
  Membership membership = Membership::position;
  Reassignment reassignment = Reassignment::lowest_ids;
  std::uint64_t seed = 0; // Reassignment::random
};

// The line of Fig. 7 that set a target.
enum class TargetRule {
  centre,    // line 31: reassigned to g ≠ h, sent to o_g
  nearest,   // line 33: not on Γ_h, sent to the nearest point of Γ_h
  first,     // line 35: the first of seq, to Γ_h(inf P_h)
  last,      // line 36: the last of seq, to Γ_h(sup P_h)
  spacing,   // line 38: p + ρ1·((p_{k−1} + p_{k+1})/2 − p)
  off_curve, // Γ_h = ∅ (line 33's min over ∅ is undefined): keeps its position (decision)
};

struct Target {
  RobotId robot = 0;
  RegionId assigned = 0; // h, or the g it is reassigned to
  RationalPoint position;
  TargetRule rule = TargetRule::off_curve;
  friend bool operator==(const Target&, const Target&) = default;
};

struct Move {
  RobotId robot = 0;
  RegionId from = 0;
  RegionId to = 0;
  friend bool operator==(const Move&, const Move&) = default;
};

struct PositionRound {
  std::size_t round = 0;
  std::vector<Robot> robots;     // at the start of the round, by increasing id
  std::vector<RegionId> members; // members[i]: the VN robots[i] reports to
  Counts counts;                 // per region, from members
  Flow flow;                     // assign, in RoundSystem's default order
  std::vector<Move> reassigned;  // the robots assign moved, by increasing id
  std::vector<Target> targets;   // calctarget's target of every robot, by increasing id
  // Robots that report next round to a VN other than the one that assigned them in this
  // round (from: assigned, to: next VN), by increasing id.
  std::vector<Move> migrations;
};

struct PositionRun {
  std::vector<PositionRound> rounds;
  std::vector<Robot> last; // after the last round
  // The first round t that certifies that the assignment is fixed from t on
  // (PositionSystem::certifies_fixed), if any within the run.
  std::optional<std::size_t> fixed_from;
};

class PositionSystem {
public:
  // The grid and q come from the curve. Throws std::invalid_argument on bad parameters
  // (as RoundSystem).
  PositionSystem(ExactCurve curve, McParams params, PositionOptions options = {});

  const ExactCurve& curve() const { return curve_; }
  const RoundSystem& counts() const { return counts_; }
  const PositionOptions& options() const { return options_; }

  // Throws std::invalid_argument (one line) unless ids are distinct and increasing,
  // positions lie in [0, m·b]², and `assigned` names a region.
  void check_robots(const std::vector<Robot>& robots) const;

  // The VN a robot reports to at the start of a round (Membership).
  RegionId member_of(const Robot& robot) const;

  // calctarget of VN_h (Fig. 7 lines 26–38) for the robots reporting to it: assigned[i]
  // is where assign put members[i] (h, or a neighbour g). Targets in the order of members.
  std::vector<Target> calctarget(RegionId h, const std::vector<Robot>& members,
                                 const std::vector<RegionId>& assigned) const;

  // One round from `robots` (round number t for Reassignment::random) and the robots
  // after it.
  PositionRound round(const std::vector<Robot>& robots, std::size_t t = 0) const;
  static std::vector<Robot> after(const PositionRound& round);

  // Whether round t certifies that the assignment is fixed from t on: no robot ever
  // changes VN again, and positions then follow e(k+1) = T·e(k) (seed 002 Lemma 7).
  bool certifies_fixed(const PositionRound& round) const;

  // `rounds` rounds from `start`, every round kept.
  PositionRun run(std::vector<Robot> start, std::size_t rounds) const;

private:
  ExactCurve curve_;
  RoundSystem counts_;
  PositionOptions options_;
};

// One round as text: counts, each robot (id, position, VN), the flow, the reassigned
// robots and the migrations. For messages and the README.
std::string format_round(const PositionRound& round);

} // namespace mc
