#pragma once
// VLBcast = LBcast(R_v, d_v) (001:40, 002:85; README "VLBcast"): every message reaches
// each of its receivers once, within [0, d_v] of its send (C15, C16).

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

// One place per CN and kind of client message, per VN and kind of VN message. A send that
// finds its place taken sets `overflow` (the model's bound; config.cpp's limits make it
// unreachable).
tioa::Automaton vlbcast(const VnConfig& config);

} // namespace vn_layer
