#pragma once
// The one-step semantics of an automaton over discretised time: from a state, every
// discrete transition (every action, every parameter value, every choice) and then one
// tick of time. Inputs of the automaton itself are driven by its environment: they may
// occur in any state, with any parameter value of their box.
//
// Time: in a timed automaton a tick lasts one quantum and discrete steps take no time;
// in an untimed one each discrete step counts as one unit ("steps").

#include <string>
#include <vector>

#include "tioa/automaton.hpp"
#include "tioa/candidates.hpp"

namespace tioa {

// TIOA are input-enabled (seed 000 §3.1): an input whose precondition is false in an
// explored state is a model error, not a disabled action.
[[noreturn]] void throw_input_not_enabled(const ActionSignature& action, const Params& params);

struct StepLabel {
  static constexpr std::uint32_t tick = 0xffffffffu;
  std::uint32_t action = tick;
  Params params;
  std::uint32_t choice = 0;
  bool is_tick() const { return action == tick; }
};

class SuccessorGenerator {
public:
  explicit SuccessorGenerator(const Automaton& automaton)
      : automaton_(&automaton), words_(automaton.words()) {
    for (const Transition& t : automaton.transitions()) {
      const TransitionPart& owner = t.parts.front();
      Entry e;
      e.simple =
          t.parts.size() == 1 && owner.base == 0 && owner.frozen_by.empty() && !owner.choice_effect;
      e.guard = owner.guard ? &owner.guard : nullptr;
      e.effect = owner.effect ? &owner.effect : nullptr;
      table_.push_back(e);
    }
  }

  std::uint32_t words() const { return words_; }
  bool timed() const { return automaton_->timed(); }
  const Automaton& automaton() const { return *automaton_; }

  // Time a step takes: a tick in a timed automaton, any step in an untimed one.
  std::uint32_t duration(const StepLabel& label) const {
    return timed() ? (label.is_tick() ? 1u : 0u) : 1u;
  }

  // Calls emit(successor, label) for each successor; `scratch` holds words()+1 words.
  // The successor buffer is only valid during the call. Returns the number emitted.
  template <class Emit>
  std::size_t successors(const Word* state, Word* scratch, Emit&& emit) const {
    std::size_t count = 0;
    const State from(state, 0);
    const auto& actions = automaton_->actions();
    const auto& transitions = automaton_->transitions();
    StepLabel label;
    for (std::uint32_t a = 0; a < actions.size(); ++a) {
      const Transition& t = transitions[a];
      const Entry& entry = table_[a];
      label.action = a;
      for_each_candidate(actions[a], t, from, [&](const Params& p) {
        if (entry.simple ? entry.guard && !(*entry.guard)(from, p) : !t.enabled(from, p)) {
          if (actions[a].kind == ActionKind::input)
            throw_input_not_enabled(actions[a], p);
          return;
        }
        label.params = p;
        if (entry.simple) { // one author's guard and effect, as most actions are
          copy_state(scratch, state);
          State to(scratch, 0);
          if (entry.effect)
            (*entry.effect)(to, p);
          label.choice = 0;
          emit(static_cast<const Word*>(scratch), static_cast<const StepLabel&>(label));
          ++count;
          return;
        }
        const std::uint32_t choices = t.choice_count(from, p);
        for (std::uint32_t c = 0; c < choices; ++c) {
          copy_state(scratch, state);
          State to(scratch, 0);
          t.apply(to, p, c);
          label.choice = c;
          emit(static_cast<const Word*>(scratch), static_cast<const StepLabel&>(label));
          ++count;
        }
      });
    }
    const Trajectories& traj = automaton_->trajectory();
    if (traj.timed && !traj.stops(from)) {
      copy_state(scratch, state);
      State to(scratch, 0);
      traj.evolve(to);
      emit(static_cast<const Word*>(scratch), StepLabel{});
      ++count;
    }
    return count;
  }

  std::string describe(const StepLabel& label) const {
    if (label.is_tick())
      return "tick";
    std::string text = automaton_->actions()[label.action].label(label.params);
    if (label.choice != 0)
      text += " [choice " + std::to_string(label.choice) + "]";
    return text;
  }

private:
  // States are a few words: a plain loop beats a call to memcpy.
  void copy_state(Word* to, const Word* from) const {
    for (std::uint32_t i = 0; i < words_; ++i)
      to[i] = from[i];
  }

  // Each action's transition, read once: when it is one part at the start of the state
  // that no Fail freezes and that has no choice (most are), its guard and effect are
  // called directly.
  struct Entry {
    bool simple = false;
    const Guard* guard = nullptr; // null: always enabled
    const Effect* effect = nullptr;
  };

  const Automaton* automaton_;
  std::uint32_t words_;
  std::vector<Entry> table_;
};

} // namespace tioa
