#pragma once
// CN(δ)_i of seed 001 Fig. 2 (001:82–131) = seed 002 Fig. 5 (002:125–156), with the
// failures of 001:36 / 002:35 (README "CN").

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

// Variables: failed, phase (realtime mod δ), x (x_i: RW's x̄_i, C21), target (x*), round,
// next_exch, next_target (round numbers as −1 past, 0 this round, 1 next round; ⊥
// before init), zone (the zone last announced by enter_i), late_target_update (observer
// of (T3), README "Observers").
tioa::Automaton cn(const VnConfig& config, int i);

// The relative round numbers of `round`, `next_exch`, `next_target`.
inline constexpr int past_round = -1, next_round = 1;

} // namespace vn_layer
