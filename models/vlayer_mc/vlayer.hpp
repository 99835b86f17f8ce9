#pragma once
// VLNodes[MC] and VLayer[MC] (seed 000 Def 4.1, line 658; §5.5, lines 966–972):
//
//   VLNodes[MC] = ‖_p Fail(VBDelay_p ‖ CN_p)  ‖  ‖_u Fail(VN_u)      (D7: VBDelay_u is the
//   identity) VLayer[MC]  = VLNodes[MC] ‖ RW ‖ VW ‖ VBcast
//
// Component names: "CN_p" (variables "CN_p.cn.x", "CN_p.delay.held", "CN_p.failed"), "VN_u"
// ("VN_u.clock", "VN_u.failed"), "RW", "VW", "VBcast", "ClientFaults". Every node is
// fail-transformed (§5.5). Fail(VBDelay_p ‖ CN_p) has the inputs fail_CN_p / restart_CN_p,
// outputs of ClientFaults (robot failures come from outside the layer); Fail(VN_u) has
// fail_VN_u / restart_VN_u, outputs of VW (D13). Each source enables them only when its
// `Faults` flag holds, so with the flag off they never fire: that is the system from t0 on,
// after the last failure. Failures before t0 are the start states with `failed` set
// (U(VLNodes) covers them).

#include <vector>

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// Which failures and restarts may happen from the start on (robots: of the clients, vsas:
// of the VSAs).
struct Faults {
  bool robots = true;
  bool vsas = false;
};

// The nodes, in the order CN_0..CN_{N−1}, VN_0..VN_{|U|−1}.
std::vector<tioa::Automaton> vlnodes_components(const VlConfig& config);
tioa::Automaton vlnodes(const VlConfig& config);
// The source of the clients' fail_CN_p / restart_CN_p, enabled only when robot_faults.
tioa::Automaton client_faults(const VlConfig& config, bool robot_faults);
// RW ‖ VW ‖ VBcast ‖ ClientFaults: everything outside VLNodes[MC].
tioa::Automaton environment(const VlConfig& config, Faults faults = {});
tioa::Automaton vlayer(const VlConfig& config, Faults faults = {});

// One start state of VLayer[MC]: every variable at its declared initial value, no node
// failed, robot p at locations[p] (RW's start leaves loc arbitrary). Enumerating the start
// set of Fail(...) itself would visit every valuation of the failed nodes.
tioa::StartSet placed_start(const tioa::Automaton& layer, const std::vector<Point>& locations);

// The robots' start points of the instance (VlConfig::place).
std::vector<Point> start_points(const VlConfig& config);

} // namespace vlayer_mc
