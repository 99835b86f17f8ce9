#pragma once
// Who is where, and the VN failures and restarts that follow from it (001:38, 002:83;
// docs/design/vn-layer.md C9–C11, README "Zones"): the environment of the VNs.

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

// Zones: zone[i] (from enter_i), active[i] (from fail/recover of CN_i), vn_failed[h] and
// occupied_for[h] (how long some active CN has been in B_h without a break, capped at d_r).
// Outputs fail_VN_h (when vn_fail allows) and recover_VN_h (enabled while VN_h is failed and
// an active CN is in B_h; due when that has lasted d_r).
tioa::Automaton zones(const VnConfig& config);

// The source of fail_CN_i / recover_CN_i: enabled only with cn_faults (failures after the
// start; the figures' premises exclude them, 002:234).
tioa::Automaton client_faults(const VnConfig& config, bool cn_faults);

} // namespace vn_layer
