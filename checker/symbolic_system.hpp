#pragma once
// An automaton's steps as learned relations (symbolic_learning.hpp), and the fixpoints the
// symbolic checks are made of. Fixpoints chain: each step group is applied in turn to the
// states not yet expanded, including those the groups before it just added.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checker/symbolic_learning.hpp"

namespace checker::symbolic {

// Thrown by a fixpoint of a System whose stop condition became true (set_stop), or by its
// construction (the stop given to it).
struct Stopped {};

class System {
public:
  // Learns every action and the tick of `space`'s automaton. `stop` and `report` are asked
  // and told while it learns (Stopped when stop says true; "learning tick, 8192 cubes") and
  // then become set_stop and set_progress.
  System(const Space& space, LearningFigures& figures, std::function<bool()> stop = {},
         std::function<void(const std::string&)> report = {});

  const Space& space() const { return *space_; }
  const StepRelation& tick() const { return tick_; }
  // Asked at every round of every fixpoint; when it says true, the fixpoint throws Stopped.
  void set_stop(std::function<bool()> stop) { stop_ = std::move(stop); }
  // Told at every round of every fixpoint what is being computed, for a progress line
  // (checker/progress.hpp): "time layer 3: zero-time closure, round 12, 1.4 M BDD nodes".
  void set_progress(std::function<void(const std::string&)> report) { report_ = std::move(report); }
  // What the rounds reported from now on belong to ("time layer 3"); empty: nothing said.
  void set_stage(std::string stage) const { stage_ = std::move(stage); }
  // States known to stay in the legal set for good (check_stabilisation's `settled`): they
  // take no step, and time passes in them (one tick leads back to the same state). None
  // unless set.
  void set_settled(bdd settled) { settled_ = std::move(settled); }
  const bdd& settled() const { return settled_; }

  // One tick from `set`, and the states of `within` one tick leads into `set`.
  bdd tick_image(const bdd& set) const;
  bdd tick_preimage(const bdd& set, const bdd& within) const;

  // `set` and every state its zero-time steps lead to (for an untimed automaton: every step).
  bdd zero_time_closure(const bdd& set) const;
  // `set` and the states of `within` whose zero-time steps inside `within` lead into it.
  bdd back_zero_time_closure(const bdd& set, const bdd& within) const;
  // Whether everything reachable from `set` (ticks included) lies in `inside`: the states
  // reachable inside it are expanded until a step leaves it (false) or none is left (true).
  bool stays_within(const bdd& set, const bdd& inside) const;
  // Everything reachable from `set`, ticks included; and everything that reaches it.
  bdd reach(const bdd& set) const;
  bdd back_reach(const bdd& set) const;
  // The states of `goal` that reach `set` (inside `within`, ticks included when `with_tick`)
  // in the fewest rounds: the backward closure stops at the first round that meets `goal`
  // (empty: `goal` never reaches `set`). For a witness, which needs one such state, not all.
  bdd nearest_back(const bdd& set, bool with_tick, const bdd& within, const bdd& goal) const;
  // The states of `within` from which no tick can ever come (zero-time steps only: the
  // time-locks of a timed automaton).
  bdd time_locks(const bdd& within) const;
  // The states of `within` from which zero-time steps can go on for ever inside `within`
  // (none at once when zero_time_acyclic()).
  bdd zero_time_forever(const bdd& within) const;
  // Whether the zero-time steps have no cycle, proved by no_cycle_proved
  // (symbolic_acyclic.hpp; computed once); false: not proved.
  bool zero_time_acyclic() const;
  // The states of `within` that are stuck: not settled, no tick and no zero-time step.
  bdd stuck(const bdd& within) const;

private:
  // `goal` (backward only; bddfalse: none): stop at the first round whose states meet it.
  bdd closure(const bdd& set, bool with_tick, bool backward, const bdd& within,
              const bdd& goal = bddfalse) const;
  // At the start of a fixpoint's round (`group` empty) and before each of its groups
  // (`group`: its name), so that a stop or a time limit is not held up by a whole round
  // (minutes on 1x2): asks stop_ (throws Stopped) and tells report_.
  void next_group(const char* fixpoint, std::uint32_t round, const std::string& group) const;

  const Space* space_;
  std::vector<StepRelation> zero_time_;
  StepRelation tick_;
  std::function<bool()> stop_;
  std::function<void(const std::string&)> report_;
  mutable std::string stage_;
  bdd settled_ = bddfalse;
  mutable std::optional<bool> zero_time_acyclic_;
};

} // namespace checker::symbolic
