#pragma once
// Questions about one state of the emulation, for its transitions (urgency) and for the
// checks (liveness of the emulated VN, the abstract state, replica consistency).

#include <optional>
#include <string>

#include "models/vn_emulation/slots.hpp"

namespace vn_emulation {

// timestamp(age) > timestamp(than) for ids kept as ages, ⊥ (-1) below every id (D21).
inline bool later_id(int age, int than) {
  return age >= 0 && (than < 0 || age < than);
}

// The zone PN_i stands in (RW's x_i; 0 with one zone).
int point_zone(const Slots& slots, const State& s, int i);
// PN_i is up and its VNE's zone h is where it stands (x ∈ B_h).
bool in_zone(const Slots& slots, const State& s, int i);
// h when in_zone(i), else -1.
int vne_zone(const Slots& slots, const State& s, int i);

// Some locally controlled action of PN_i is enabled (002:410: "Stop when any
// Precondition is satisfied"; TOBcast delivers exactly at ts + d_p + ε).
bool pn_urgent(const Slots& slots, const State& s, int i);
// Time cannot pass: some PN is urgent, or an LBcast packet is due (age d_p with receivers
// left). (A state past the model's bounds is not expanded by the checks.)
bool urgent(const Slots& slots, const State& s);

// VN_h is alive (D18, §1.8): an up VNE of the zone is active, or a listening one will
// adopt a join-ack already sent (in its buffer, or in flight to it).
bool vn_alive(const Slots& slots, const State& s, int h = 0);
// val_abs (§1.8): the val of the first active replica of zone h, else of the join-ack a
// listening replica will adopt; nullopt when VN_h is failed.
std::optional<VnValue> abstract_value(const Slots& slots, const State& s, int h = 0);

// P1 (§4.3) at a state where time can pass: two active replicas of a zone with different vals, or
// an active replica with actions still pending; in words. nullopt when it holds or when
// time cannot pass here.
std::optional<std::string> replica_failure(const Slots& slots, const State& s);

} // namespace vn_emulation
