#pragma once
// The parameters of VLayer[MC] (issue 4 names): the grid, the robots, the lattice, and the
// constants of seed 000 §4–5, every time a whole number of quanta.

#include <memory>
#include <optional>
#include <string>

#include "models/mc/rational.hpp"
#include "models/vlayer_mc/lattice.hpp"

namespace vlayer_mc {

class BranchTally;

// Where the robots start (the instance's start state; the lemmas of §7.2 start anywhere):
// `row` robot p at (p, rows·b), the lattice's last row (drawn at the bottom), off the curve;
// `corner` every robot at (0, rows·b). Robots are points, and nothing in RW, CN or VN keeps
// two apart, so a common point is one of the paper's start states: the smallest lattice on
// which 5 robots share a region (issue 15, README "Where each branch of Fig. 7 acts").
enum class Placement { row, corner };

struct VlConfig {
  int rows = 1, cols = 2;
  mc::Neighbourhood nbh = mc::Neighbourhood::four;
  int robots = 1;
  int b = 2; // lattice units per region side
  // The cheap constants of the README: 0 + 3 + 0 + 1 + 1 = 5 < δ = 6.
  int delta = 6, d = 1, e = 0, eps = 0, eps_sample = 1, d_r = 1, vmax = 4;
  int k = 1;
  mc::Rational rho1{1, 2}, rho2{9, 10};
  Placement place = Placement::row;
  // Changes to the paper's CN and VN, each off by default (the paper's reconstruction) and
  // each a no-op on every state reachable without failures (README "Self-stabilising CN and
  // VN"). The first runs of lemma-7.3 led to them.
  // D25: a GPSupdate that finds the CN's view wrong resets v_p and x*_p, and drops a target
  // the robot cannot reach in the round (Def 7.1(4b)).
  bool cn_repair = false;
  // D26: VN_u empties M_u on a time update that corrects its clock or comes after
  // e + 2d + 2ε, and ignores a cn-update after e + d + ε.
  bool vn_repair = false;
  // D28: a CN ignores a target-update that arrives outside [e + 2d + 2ε, e + 3d + 2ε] or
  // that it could not reach in the round (Def 7.1(4b)). It hides what a too short round
  // breaks (F3); Lemma 7.3 needs it (F5).
  bool filter_targets = false;
  // D14: calctarget's lines 35–36 send the first and last robot of seq to Γ_u(inf P_u) and
  // Γ_u(sup P_u). Under half-open ownership sup P_u lies in the next region when u is not in
  // the last column, so the robot sent there stands in the next region and reports to its
  // VN. With owned_ends, P_u is the part of Γ_u that u owns (up to sup P_u − 1 on the
  // lattice), for lines 33 and 35–38.
  bool owned_ends = false;
  // D32, the d_r rule (seed 000 lines 1176–1178, a guarantee of the VSA layer's emulation):
  // VW never fails VN_u while a live client has been in u for d_r with no live client
  // failing in u or leaving it, and restarts VN_u when that begins. Off: VW fails and
  // restarts VSAs as Def 4.1 lets it (with vsa_faults), the rule not enforced.
  bool dr_rule = false;
  // D31: the capacity of the junk slots of each client's VBDelay (the messages of any kind
  // and id that U(VLNodes) may leave in it) and of VBcast (those messages on their way).
  // No step fills an empty junk slot, so on every state reachable from a state without junk
  // they stay empty: only the automata of the arbitrary start states have them
  // (proofs/vlayer_mc/arbitrary_starts.hpp, the parameter `junk`); 0 leaves them out.
  int junk = 0;
  // Not a parameter: where VN_u's compute steps count the branches of Fig. 7 they take
  // (branch_tally.hpp); null counts nowhere. Every automaton built from this config shares
  // it.
  std::shared_ptr<BranchTally> branch_tally;

  Lattice lattice() const { return Lattice(rows, cols, b, nbh); }
  // Phases (clock mod δ) at which VN_u sends its vn-update and computes the targets (D1).
  int vn_update_phase() const { return e + d + eps; }
  int target_phase() const { return e + 2 * d + 2 * eps; }
};

// 2e + 3d + 2ε + ⌈r/v_max⌉ + d_r: δ must exceed it (seed 000 §5.5, line 981).
int round_length_bound(const VlConfig& config);
bool round_length_ok(const VlConfig& config);

// Why the values cannot build a model (ranges, b, the target phase within the round), or
// nullopt. The round-length rule is not checked here: breaking it is a question to ask.
std::optional<std::string> invalid(const VlConfig& config);

} // namespace vlayer_mc
