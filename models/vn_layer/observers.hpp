#pragma once
// What the conference's §V-B and §VI take from the layer, as predicates over VNLayer's
// states (docs/design/vn-layer.md §2.4; README "Observers"):
//
//  (T1) no cn-update of round k reaches VN_h after VN_h handled its first exchange-trigger
//       of round k (002:121);
//  (T2) no vn-update of round k reaches VN_h after VN_h computed the targets of round k
//       (002:123, 158);
//  (T3) a target-update reaches its CN within d_MMT + 2d_v of the CN's target-trigger
//       (002:160);
//  (T4) at the start of every round from round 1 on, before its cn-update, every active
//       CN stands on its target and the VN of its zone is alive (002:162);
//  (Y)  for every two VNs f, g that computed targets in the same round, and every zone h of
//       Nbrs_f ∪ {f} and of Nbrs_g ∪ {g}: y_f(h) = y_g(h) (002:232).
//  (R)  no active CN holds round, next-exch or next-target in a past round: its sends wait
//       for realtime = that round·δ (001 Fig. 2 lines 34–50), which never comes again, so
//       it would never report (or trigger) again. A recovery that keeps the CN's
//       variables (001:36, cn_fail=keep) after a round boundary leads there.

#include <optional>
#include <string>
#include <vector>

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

class Observers {
public:
  Observers(const tioa::Automaton& layer, const VnConfig& config);

  // The first of (T1)–(T4) the state breaks, in words; nullopt when it breaks none.
  std::optional<std::string> round_timing_failure(const tioa::State& s) const;
  // Two VNs that disagree on a count, in words; nullopt when (Y) holds in s.
  std::optional<std::string> y_failure(const tioa::State& s) const;
  // An active CN that will never send again (R), in words; nullopt when there is none.
  std::optional<std::string> silent_cn(const tioa::State& s) const;
  // A send found its place taken (vn.hpp, vlbcast.hpp): the model's bound.
  bool overflowed(const tioa::State& s) const;

private:
  struct CnSlots {
    tioa::Variable<bool> failed, late;
    tioa::Variable<int> phase, x, target, round, next_exch, next_target;
  };
  struct VnSlots {
    tioa::Variable<bool> failed, late_cn, late_vn, overflow;
    tioa::Variable<int> epoch, y_round;
    std::vector<RegionId> zones;
    std::vector<tioa::Variable<int>> y;
  };
  Lattice lattice_;
  std::vector<CnSlots> cns_;
  std::vector<VnSlots> vns_;
  tioa::Variable<bool> channel_overflow_;
};

} // namespace vn_layer
