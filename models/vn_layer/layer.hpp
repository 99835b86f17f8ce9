#pragma once
// The conference virtual-node layer (seed 001 §2, seed 002 §V-A): CNs, VNs, VLBcast and
// their environment, composed by actions (README "Components"):
//
//   VNLayer = ‖_i CN_i ‖ ‖_h VN_h ‖ VLBcast ‖ Zones ‖ ClientFaults
//
// Component names "CN_i" (variables "CN_i.x", "CN_i.target", …), "VN_h", "VLBcast", "Zones",
// "ClientFaults". RW is not a component: its realtime is each component's phase copy and
// its x̄_i is CN_i's x (C21).

#include <string>
#include <vector>

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

tioa::Automaton vn_layer(const VnConfig& config, bool cn_faults = false);

// The start states at time 0 with CN_i at locations[i] and active, every other variable at
// its declared initial value (VNs failed unless vns_start_failed is off): one placement, or
// every placement of the CNs on lattice points (002:53, "initially arbitrary").
tioa::StartSet placed_start(const tioa::Automaton& layer, const VnConfig& config,
                            const std::vector<Point>& locations);
tioa::StartSet every_placement(const tioa::Automaton& layer, const VnConfig& config);

} // namespace vn_layer
