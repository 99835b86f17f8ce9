#pragma once
// VLNodes[MC] and VLayer[MC] (seed 000 Def 4.1, line 658; §5.5, lines 966–972):
//
//   VLNodes[MC] = ‖_p Fail(VBDelay_p ‖ CN_p)  ‖  ‖_u Fail(VN_u)      (D7: VBDelay_u is the
//   identity) VLayer[MC]  = VLNodes[MC] ‖ RW ‖ VW ‖ VBcast
//
// Component names: "CN_p" (variables "CN_p.cn.x", "CN_p.delay.held", "CN_p.failed"), "VN_u"
// ("VN_u.clock", "VN_u.failed"), "RW", "VW", "VBcast". Fail(VBDelay_p ‖ CN_p) has the inputs
// fail_CN_p / restart_CN_p (driven by the environment: robot failures); Fail(VN_u) has
// fail_VN_u / restart_VN_u, outputs of VW when vsa_faults holds (D13).

#include <vector>

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer {

// Which failures the system has. With robots = false the nodes VBDelay_p ‖ CN_p are not
// fail-transformed: the executions of Fail(A) in which no fail occurs (failed stays false)
// are those of A, so this is VLayer[MC] from t0 on, after the last robot failure or restart.
// vsa = false: VW issues no fail_u/restart_u (D13); Fail(VN_u) keeps its inputs.
struct Faults {
  bool robots = true;
  bool vsas = false;
};

// The nodes, in the order CN_0..CN_{N−1}, VN_0..VN_{|U|−1}.
std::vector<tioa::Automaton> vlnodes_components(const VlConfig& config, Faults faults = {});
tioa::Automaton vlnodes(const VlConfig& config, Faults faults = {});
// RW ‖ VW ‖ VBcast.
tioa::Automaton environment(const VlConfig& config, Faults faults = {});
tioa::Automaton vlayer(const VlConfig& config, Faults faults = {});

// One start state of VLayer[MC]: every variable at its declared initial value, no node
// failed, robot p at locations[p] (RW's start leaves loc arbitrary). Enumerating the start
// set of Fail(...) itself would visit every valuation of the failed nodes.
tioa::StartSet placed_start(const tioa::Automaton& layer, const std::vector<Point>& locations);

} // namespace vlayer
