#pragma once
// L_round, the legal set of the conference layer at its round starts. The conference papers
// state none (seed 002 §VI proves Theorem 1 from the round-length condition, 002:162); this
// one is ours, in the style of the journal's ResetMC (docs/design/vn-layer.md §5.3, check
// 4). A state is in L_round when, at realtime kδ with k ≥ 1 and before any round-k
// cn-update:
//   (R1) every active CN has round = next-exch = next-target = k (its round counters are
//        "this round"), x* ≠ ⊥ and x_i = x*;
//   (R2) every zone holding an active CN has an alive VN;
//   (R3) every VN has an empty send-buffer, vn-done ≠ k and target-done ≠ k, and no round-k
//        tag in M or V (their contents of earlier rounds are free);
//   (R4) VLBcast holds nothing (no place holds a message; what an empty place last held
//        is free);
//   (R5) every component's copy of realtime is kδ, and every copy of a CN's zone, of its
//        being active and of a VN's being failed agrees with the CN's position, the CN and
//        the VN (C21: RW's x̄_i is CN_i's x); a zone with no active CN has counted no time
//        of occupancy (Zones restarts the count when a zone empties).
// The observers (the sticky flags of round-timing, y, the last exchange) are free.
//
// Classes. Within one round from an L_round state, every message a VN handles was sent in
// that round (VLBcast is empty at its start), so it carries the tag "this round", and every
// stored tag of an earlier round compares unequal to it whatever its value. So the contents
// of earlier rounds are never read, with one exception: a VN that handles a target-trigger
// of the round without having handled an exchange-trigger of it counts M's entries of
// earlier rounds (Fig. 3 lines 44–54 filter V by round, not M). Apart from that case, two
// L_round states that differ only in
//   - M's and V's entries of earlier rounds, vn-done and target-done (all of earlier
//     rounds), the empty send-buffer's places and the MMT clock,
//   - the round counts of the realtime copies (k ≥ 1 only decides which stale tag a reset
//     writes), the observers,
//   - a failed CN's internal variables (without CN failures after the start it never
//     recovers, so nothing reads them), and what VLBcast's empty places last held,
// have the same rounds up to those values, and so the same next round starts up to them.
// `canonicalise` maps an L_round state to its class's representative; round_closure.cpp
// checks that the exception never happens in the rounds it explores (`stale_reader`).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/vn_layer/config.hpp"
#include "tioa/automaton.hpp"

namespace vn_layer {

class RoundLegalSet {
public:
  // `layer`: the layer (vn_layer()) or any automaton with its variables.
  RoundLegalSet(const tioa::Automaton& layer, const VnConfig& config);

  bool contains(const tioa::Word* state) const { return !first_broken(state, nullptr); }
  // The clause the state breaks, in words ("R1: CN_0 is not on its target: x = 3, x* = 5"),
  // or nullopt when it is in L_round.
  std::optional<std::string> broken(const tioa::Word* state) const;

  // Replaces the values the classes ignore by their representative's (an L_round state
  // stays one; a state outside L_round must not be given). A representative's copies of
  // realtime say round 1 (`last_round` as the age of round 0), so the round starts its
  // round leads to, which say round 2 or later, differ from it until canonicalised.
  void canonicalise(tioa::Word* state) const;

  // A VN that may have counted M's entries of earlier rounds (see above): alive, with
  // target-done = this round and vn-done ≠ this round. nullopt when there is none.
  std::optional<RegionId> stale_reader(const tioa::Word* state) const;

  // A component's `overflow` flag: a send found the model's places taken (a bound of the
  // model, not of the layer).
  bool overflowed(const tioa::Word* state) const;

  // One state per class, states() words each, in a fixed order: every CN active at a
  // lattice point or failed at one, every VN of a zone without an active CN alive or failed,
  // every count 0..d_r of occupancy in a zone with one.
  std::vector<tioa::Word> representatives() const;
  std::uint32_t words() const { return words_; }

private:
  struct Cn {
    tioa::Variable<bool> failed, late_target_update;
    tioa::Variable<int> phase, epoch, x, target, round, next_exch, next_target, zone;
  };
  struct Vn {
    tioa::Variable<bool> failed, overflow;
    tioa::Variable<int> phase, epoch, vn_done, target_done, task;
    std::vector<tioa::Variable<int>> M, M_round, V_round;
    std::vector<tioa::Slot> buffer;  // the kinds of the send-buffer's places
    std::vector<tioa::Slot> to_init; // what the representative holds at its initial value
    std::vector<std::uint64_t> init_codes;
  };
  // Writes the clause broken into `why` (when not null); true when one is.
  bool first_broken(const tioa::Word* state, std::string* why) const;

  VnConfig config_;
  Lattice lattice_;
  std::uint32_t words_;
  std::vector<tioa::VariableInfo> all_;
  std::vector<Cn> cns_;
  std::vector<Vn> vns_;
  tioa::Variable<int> bcast_phase_, bcast_epoch_;
  tioa::Variable<bool> bcast_overflow_;
  // VLBcast's places: whether each holds a message (0: none), and what a message in one
  // is (read only while it holds one).
  std::vector<tioa::Slot> bcast_in_flight_, bcast_contents_;
  std::vector<std::uint64_t> bcast_empty_;
  std::vector<tioa::Variable<int>> zone_of_;
  std::vector<tioa::Variable<bool>> active_, vn_failed_;
  std::vector<tioa::Variable<int>> occupied_for_;
};

} // namespace vn_layer
