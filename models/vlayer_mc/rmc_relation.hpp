#pragma once
// The simulation relation R_MC of seed 000 §7.3 (lines 1300–1335), the relation of
// Lemmas 7.6 and 7.7 (proofs/lemma_7_6.hpp, proofs/lemma_7_7.hpp).
//
// The paper gives only "some of the conditions" (Appendix C is not in the seed):
//   (1) the same real time and locations,  (2) per client: RW's velocity equal or y's ⊥,
//   GPSupdate records for the same times,  (3) VW's state and Vbcast.now equal,
//   (4) the unprocessed message tuples and Vbcast's last recorded regions equal.
// The rest is ours (models/vlayer_mc/README.md, "R_MC (Lemmas 7.6–7.7)", D17–D21):
//   (2) under D8 (a robot moves only towards the point RW.vel holds): RW.vel(p) equal, or
//       y's is ⊥ and x's robot stands (⊥ or 0)                                      [D17]
//   (4) a VBcast slot with no pending receiver is an empty slot: its leftover age and
//       payload are not compared                                                    [D18]
//   (5) every node: `failed` equal; a node failed in both is not compared further (Fail
//       freezes it, and restart overwrites it); a live node's state is equal, VBDelay_p's
//       leftover age and location excepted when it holds nothing                    [D19]
//   (5′) the loose readings only: CN_p's target x*_p may differ while the cn-update is due
//       (clock_p = 0, not yet sent at this instant, x_p ≠ ⊥) if both targets are ⊥ or x_p:
//       the vcast due before time passes sets x*_p := ⊥, and until then x*_p is read only
//       through the desired velocity, 0 in both                                      [D20]
//   (4′) the reading `loose_reg` only, beyond the printed part (4): Vbcast.reg(p) may differ
//       while p's GPSupdate is due (RW lets no time pass first, and it overwrites reg(p))
//       and nothing can read reg(p) before it: CN_p live with x_p = ⊥ (no cn-update), its
//       VBDelay empty, no VN_u about to vcast a target for p                        [D21]
// Every variable of the layer is accounted for by exactly one part (a new variable is a
// ModelError until it is given a part).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer_mc {

// Which reading of the parts the paper leaves open: `strict` compares all of a live CN;
// `loose` adds (5′); `loose_reg` adds (4′) too, departing from the printed part (4). The
// checks of Lemmas 7.6 and 7.7 decide with `loose` unless told, and lemma-7.7 reports all three
// counts.
enum class RmcReading { strict, loose, loose_reg };

const char* to_string(RmcReading reading);

class RmcRelation {
public:
  // `layer` is VLayer[MC] of `config` (any Faults: they do not change the variables).
  RmcRelation(const VlConfig& config, const tioa::Automaton& layer,
              RmcReading reading = RmcReading::loose);

  RmcReading reading() const { return reading_; }
  // x R_MC y, for two states of `layer`.
  bool related(const tioa::Word* x, const tioa::Word* y) const;
  // The conditions x and y break, e.g. "(1) RW.loc[0]", "(5) CN_0.cn.target"; empty iff related.
  std::vector<std::string> broken(const tioa::Word* x, const tioa::Word* y) const;
  // A hash of everything both readings require equal: related states have equal keys.
  std::uint64_t key(const tioa::Word* state) const;

private:
  struct Guarded {    // fields compared only when the guard is nonzero (in both)
    tioa::Slot guard; // compared always
    std::vector<tioa::Slot> fields;
    std::string part; // "(4)" or "(5)"
  };
  struct Node { // a fail-transformed node CN_p or VN_u
    tioa::Slot failed;
    std::vector<tioa::Slot> equal;
    std::vector<Guarded> guarded;
    bool client = false; // CN_p: has the fields below
    tioa::Slot clock, x, target, since;
  };
  struct Region { // Vbcast.reg(p) and what (4′) reads to decide it is not read
    tioa::Slot reg, gps_age, failed, x, held;
    std::vector<tioa::Slot> out; // VN_u.out[p] for every u
  };
  struct Velocity {
    tioa::Slot vel;
  };

  template <class Report>
  bool compare(const tioa::Word* x, const tioa::Word* y, Report&& report) const;

  RmcReading reading_;
  std::vector<std::pair<tioa::Slot, std::string>> equal_; // (slot, part) of RW, VW, VBcast
  std::vector<Guarded> messages_;
  std::vector<Velocity> velocities_;
  std::vector<Region> regions_;
  std::int64_t eps_sample_ = 1;
  std::vector<Node> nodes_;
};

} // namespace vlayer_mc
