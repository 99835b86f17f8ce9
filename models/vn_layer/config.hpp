#pragma once
// The parameters of the conference virtual-node layer (seed 001 §2–3, seed 002 §V; the
// decisions C1–C32 of docs/design/vn-layer.md, as built in README.md): the grid, the
// client nodes, the lattice, and the constants of the layer, every time a whole number of
// quanta.

#include <memory>
#include <optional>
#include <string>

#include "models/mc/rational.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/lattice.hpp"

namespace vn_layer {

using vlayer_mc::Lattice;
using vlayer_mc::Point;
using vlayer_mc::RegionId;

// How a CN fails (C8): seed 002 §II (002:35) resets its internal variables; seed 001
// (001:36) keeps them, so a recovered CN whose rounds lie in the past never sends again.
enum class CnFail { reset, keep };
// When a VN may fail (C10): never; only while no active CN is in its zone (the emulation,
// 002:350–352); at any time (the layer's text puts no condition on fail_h).
enum class VnFail { never, empty, any };

struct VnConfig {
  int rows = 2, cols = 1;
  mc::Neighbourhood nbh = mc::Neighbourhood::four; // C28: 001:32, 002:71
  int cns = 2;                                     // client nodes CN_0..CN_{cns−1}
  int b = 2;                                       // lattice units per zone side
  // docs/design/vn-layer.md §5.2: the lattice rule (C29) asks δ > 12.
  int delta = 13, d_v = 1, d_mmt = 1, eps = 1, d_r = 1, vc = 2;
  int k = 1; // the conference's safety parameter e (C31)
  mc::Rational rho1{1, 2}, rho2{9, 10};
  CnFail cn_fail = CnFail::reset;
  VnFail vn_fail = VnFail::empty;
  bool vns_start_failed = true; // C11: no emulator has joined at time 0
  bool owned_ends = false;      // vlayer-mc's D14 variant of calctarget's lines 35–36
  // Not a parameter: where the VNs' target computations count the branches of Fig. 7 they
  // take (vlayer_mc::BranchTally, through targets_config()); null counts nowhere.
  std::shared_ptr<vlayer_mc::BranchTally> branch_tally;

  Lattice lattice() const { return Lattice(rows, cols, b, nbh); }
  // The phases (realtime − round·δ) of the CN's sends (Fig. 2 lines 34–50): cn-update at 0,
  // exchange-trigger at d_v + ε, target-trigger at d_MMT + 3d_v + 2ε.
  int exchange_phase() const { return d_v + eps; }
  int target_phase() const { return d_mmt + 3 * d_v + 2 * eps; }
  // The same instance for vlayer-mc's assign and calctarget on the lattice (C18, C19).
  vlayer_mc::VlConfig targets_config() const;
  // paper_round_bound with two decimals, for reports.
  std::string paper_round_bound_text() const;
};

// δ > 2d_MMT + 5d_v + 2ε + max(√2.5·b/v_c, √10·b/(3v_c) + d_r) (002:162, 001:143),
// decided exactly in integers.
bool paper_round_rule_holds(const VnConfig& config);
double paper_round_bound(const VnConfig& config); // the right-hand side, for reports
// The lattice's own rule (C29): 2d_MMT + 5d_v + 2ε + ⌈D/v_c⌉ + d_r, D the largest L∞
// distance from a point to a target a VN can give it (a neighbour's centre, or its zone).
int lattice_round_bound(const VnConfig& config);

// Why the values cannot build a model, or nullopt. The round rules are not checked here:
// breaking them is a question to ask.
std::optional<std::string> invalid(const VnConfig& config);

} // namespace vn_layer
