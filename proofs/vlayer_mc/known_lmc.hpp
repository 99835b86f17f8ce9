#pragma once
// LMC as far as it is known (D29, models/vlayer_mc/README.md "Stabilisation (§7.2)").

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "checker/explorer.hpp"
#include "checker/options.hpp"
#include "models/vlayer_mc/config.hpp"
#include "models/vlayer_mc/state_list.hpp"
#include "tioa/automaton.hpp"
#include "tioa/start_set.hpp"

namespace vlayer_mc {

// LMC as far as it is known (D29): the states reachable from the reset family with every
// combination of failed nodes, compared up to variables nothing reads again: a failed node
// is frozen and nothing reads its variables (a restart overwrites them); and an empty
// VBDelay or VBcast slot keeps the age and payload of its last message, which the next
// vcast overwrites. Both are set to their initial values before comparing; and a robot's
// RW.vel that moves it nowhere is written as 0. States equal up to these have successors
// equal up to them, so the classes are explored directly, one representative each
// (ExploreHooks::canonical).
class KnownLmc {
public:
  // `layer` is VLayer[MC] of `config`, with its fault actions. The exploration stops at the
  // first class where `stop_at` holds, if given (exploration().found).
  KnownLmc(const VlConfig& config, const tioa::Automaton& layer,
           const checker::ExploreOptions& options, const tioa::StatePredicate& stop_at = {});

  bool complete() const { return ex_->complete(); } // false: a limit was hit
  std::uint64_t size() const { return ex_->store.size(); }
  std::uint64_t family_size() const { return family_size_; }
  // The exploration of the classes; its parents link representatives, not a trace.
  const checker::Exploration& exploration() const { return *ex_; }
  // `layer` started in the reset family with every combination of failed nodes.
  tioa::Automaton from_family(const tioa::Automaton& layer) const;
  // Whether `s`, compared as above, is one of the known LMC states (thread-safe).
  bool contains(const tioa::State& s) const;
  // The representative of `s`'s class: `s` with what nothing reads again reset.
  std::vector<tioa::Word> representative(const tioa::State& s) const;

  // One part of the comparison: where `applies` holds of a state, `rest` is read no more,
  // and the representative has its initial codes there.
  struct Forgetting {
    enum class When {
      velocity_moves_nowhere, // `guard` is RW.vel[p], `loc` RW.loc[p]
      slot_empty,             // `guard` is a slot's pending or held flag
      node_failed             // `guard` is a node's failed flag
    };
    When when;
    tioa::Slot guard, loc;
    std::vector<std::pair<tioa::Slot, std::uint64_t>> rest; // with its initial code
    bool applies(const tioa::State& s) const;
  };
  // The parts, in the order the representative applies them (a later part sees what the
  // earlier ones set).
  const std::vector<Forgetting>& forgetting() const { return forgetting_; }

private:
  static Forgetting node(const tioa::Automaton& layer, const std::string& prefix);
  void canonical(tioa::State& s) const;

  std::uint32_t words_;
  std::vector<Forgetting> forgetting_;
  tioa::StartSet family_; // lazy: each state built as it is enumerated
  std::uint64_t family_size_ = 0;
  std::shared_ptr<checker::Exploration> ex_;
};

} // namespace vlayer_mc
