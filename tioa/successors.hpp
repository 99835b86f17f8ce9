#pragma once
// The one-step semantics of an automaton over discretised time: from a state, every
// discrete transition (every action, every parameter value, every choice) and then one
// tick of time. Inputs of the automaton itself are driven by its environment: they may
// occur in any state, with any parameter value of their box.
//
// Time: in a timed automaton a tick lasts one quantum and discrete steps take no time;
// in an untimed one each discrete step counts as one unit ("steps").

#include <algorithm>
#include <optional>
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
      const ActionSignature& sig = automaton.actions()[table_.size()];
      e.run = run_filter(sig, t);
      if (sig.params.size() == 1 && !sig.accepts && t.bindings.size() == 1 &&
          t.bindings.front().param == 0 && !t.bindings.front().filter())
        e.bound = &t.bindings.front();
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
      auto step = [&](const Params& p) {
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
      };
      // One parameter, filtered or bound: the same values, in the same order, as
      // for_each_candidate gives, without its recursion over parameters.
      if (entry.run) {
        const RunFilter& run = *entry.run;
        Params p;
        p.size = 1;
        for (std::uint64_t match = run.admitted(from); match != 0; match &= match - 1) {
          const auto bit = static_cast<std::uint32_t>(__builtin_ctzll(match));
          p.values[0] = run.first + static_cast<std::int32_t>(bit / run.width);
          step(p);
        }
      } else if (entry.bound) {
        Params p;
        p.size = 1;
        const std::optional<std::int32_t> value = entry.bound->bind(from, p);
        const ParamRange& range = actions[a].params.front();
        if (value && *value >= range.lo && *value <= range.hi) {
          p.values[0] = *value;
          step(p);
        }
      } else {
        for_each_candidate(actions[a], t, from, step);
      }
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

  // An action whose one parameter is an id that a `.where` filter admits, read as one run
  // of bits (candidates.hpp): its ids first.. with their fields at fixed places of the
  // state, so that the admitted ids are found without the candidate recursion.
  struct RunFilter {
    Slot bits;             // the fields of the ids first..last, in the whole state
    std::uint64_t pattern; // the admitted code in every field
    std::uint64_t low;     // bit 0 of every field
    std::uint32_t width;   // of a field
    std::int32_t first;    // the id of the first field
    // One bit (the lowest of its field) per admitted id, in increasing order of ids.
    std::uint64_t admitted(const State& s) const {
      return admitted_fields(s.code(bits), pattern, low, width);
    }
  };
  static std::optional<RunFilter> run_filter(const ActionSignature& sig, const Transition& t) {
    if (sig.params.size() != 1 || sig.accepts || t.bindings.size() != 1)
      return std::nullopt;
    const Binding& b = t.bindings.front();
    if (b.param != 0 || !b.filter() || !b.run)
      return std::nullopt;
    const ParamRange& range = sig.params.front();
    const std::int64_t first = std::max<std::int64_t>(range.lo, b.where_first);
    const std::int64_t last =
        std::min<std::int64_t>(range.hi, b.where_first + std::int64_t(b.where.size()) - 1);
    if (first > last)
      return std::nullopt; // (no id: the recursion returns at once too)
    RunFilter r;
    r.width = b.where.front().width;
    r.first = static_cast<std::int32_t>(first);
    const auto lo_bit = static_cast<std::uint32_t>((first - b.where_first) * r.width);
    const auto bits = static_cast<std::uint32_t>((last - first + 1) * r.width); // < 64
    r.bits = Slot::bits(b.base + b.run->offset + lo_bit, static_cast<std::uint8_t>(bits));
    r.pattern = b.run_pattern >> lo_bit;
    r.low = (b.run_low >> lo_bit) & ((std::uint64_t{1} << bits) - 1);
    return r;
  }

  // Each action's transition, read once: when it is one part at the start of the state
  // that no Fail freezes and that has no choice (most are), its guard and effect are
  // called directly.
  struct Entry {
    bool simple = false;
    const Guard* guard = nullptr; // null: always enabled
    const Effect* effect = nullptr;
    std::optional<RunFilter> run;   // its candidates, when they come from one run filter
    const Binding* bound = nullptr; // its one parameter's binder, when it has one
  };

  const Automaton* automaton_;
  std::uint32_t words_;
  std::vector<Entry> table_;
};

} // namespace tioa
