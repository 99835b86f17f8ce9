#pragma once
// LMC as far as it is known (D29, models/vlayer_mc/README.md "Stabilisation (§7.2)").

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "checker/options.hpp"
#include "checker/state_store.hpp"
#include "models/vlayer_mc/config.hpp"
#include "tioa/automaton.hpp"

namespace vlayer {

// LMC as far as it is known (D29): the states reachable from the reset family with every
// combination of failed nodes, compared up to variables nothing reads again: once no node
// fails or restarts any more, a failed node is frozen and nothing reads its variables; and
// an empty VBDelay or VBcast slot keeps the age and payload of its last message, which the
// next vcast overwrites. Both are set to their initial values before comparing; and a robot's
// RW.vel that moves it nowhere is written as 0.
class KnownLmc {
public:
  // `layer` is VLayer[MC] of `config` with no fault action enabled (after t0).
  KnownLmc(const VlConfig& config, const tioa::Automaton& layer,
           const checker::ExploreOptions& options);

  bool complete() const { return complete_; } // false: the exploration hit a limit
  std::uint64_t size() const { return known_->size(); }
  std::uint64_t family_size() const { return family_size_; }
  // Whether `s`, compared as above, is one of the known LMC states (thread-safe).
  bool contains(const tioa::State& s) const;
  // The representative of `s`'s class: `s` with what nothing reads again reset.
  std::vector<tioa::Word> representative(const tioa::State& s) const;

private:
  struct Node {
    tioa::Slot failed;
    std::vector<std::pair<tioa::Slot, std::uint64_t>> rest; // with its initial code
  };
  struct Guarded { // `rest` is read only while `guard` is nonzero
    tioa::Slot guard;
    std::vector<std::pair<tioa::Slot, std::uint64_t>> rest;
  };

  static Node node(const tioa::Automaton& layer, const std::string& prefix);
  void canonical(tioa::State& s) const;

  std::uint32_t words_;
  std::vector<Node> nodes_;
  std::vector<Guarded> slots_;
  std::vector<std::pair<tioa::Slot, tioa::Slot>> velocities_; // RW.vel[p], RW.loc[p]
  std::uint64_t family_size_ = 0;
  bool complete_ = false;
  std::shared_ptr<checker::StateStore> known_;
};

} // namespace vlayer
