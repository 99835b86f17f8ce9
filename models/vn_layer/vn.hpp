#pragma once
// VN(e, ρ1, ρ2)_h of seed 001 Fig. 3 (001:153–181) = seed 002 Fig. 6 (002:170–206), with
// the failures of 001:38 / 002:83 (README "VN").

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

// The order of V's entries: Nbrs_h by increasing id, then h itself.
std::vector<RegionId> v_zones(const Lattice& lattice, RegionId h);

// Variables: failed, phase, epoch (round_tags.hpp), M[i] with M_round[i], V_num[j] with
// V_round[j] (j over v_zones), the send-buffer as two slots (slot 0 its head) with kind,
// count, round and a target map, task (the MMT clock, C22), vn_done, target_done; and the
// observers exchanged, y_round, y[j], late_cn_update, late_vn_update, overflow (README
// "Observers").
tioa::Automaton vn(const VnConfig& config, RegionId h);

enum class Buffered { none, vn_update, target_update };
inline constexpr int buffer_slots = 2;

} // namespace vn_layer
