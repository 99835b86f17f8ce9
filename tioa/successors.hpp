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
      : automaton_(&automaton), words_(automaton.words()), timed_(automaton.timed()) {
    for (const Transition& t : automaton.transitions()) {
      const TransitionPart& owner = t.parts.front();
      Entry e;
      e.action = static_cast<std::uint32_t>(table_.size());
      e.signature = &automaton.actions()[e.action];
      e.transition = &t;
      e.input = e.signature->kind == ActionKind::input;
      e.simple =
          t.parts.size() == 1 && owner.base == 0 && owner.frozen_by.empty() && !owner.choice_effect;
      e.guard = owner.guard ? &owner.guard : nullptr;
      e.effect = owner.effect ? &owner.effect : nullptr;
      const ActionSignature& sig = *e.signature;
      e.run = run_filter(sig, t);
      if (sig.params.size() == 1 && !sig.accepts && t.bindings.size() == 1 &&
          t.bindings.front().param == 0 && !t.bindings.front().filter())
        e.bound = &t.bindings.front();
      table_.push_back(e);
    }
  }

  std::uint32_t words() const { return words_; }
  bool timed() const { return timed_; }
  const Automaton& automaton() const { return *automaton_; }

  // Time a step takes: a tick in a timed automaton, any step in an untimed one.
  std::uint32_t duration(const StepLabel& label) const {
    return timed_ ? (label.is_tick() ? 1u : 0u) : 1u;
  }

  // Calls emit(successor, label) for each successor; `scratch` holds words()+1 words.
  // The successor buffer is only valid during the call. Returns the number emitted.
  template <class Emit>
  std::size_t successors(const Word* state, Word* scratch, Emit&& emit) const {
    std::size_t count = 0;
    const State from(state, 0);
    StepLabel label;
    for (const Entry& entry : table_) {
      const Transition& t = *entry.transition;
      label.action = entry.action;
      auto step = [&](const Params& p) {
        if (entry.simple ? entry.guard && !(*entry.guard)(from, p) : !t.enabled(from, p)) {
          if (entry.input)
            throw_input_not_enabled(*entry.signature, p);
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
          p.values[0] = run.first + static_cast<std::int32_t>(run.fields.field_of(bit));
          step(p);
        }
      } else if (entry.bound) {
        Params p;
        p.size = 1;
        const std::optional<std::int32_t> value = entry.bound->bind(from, p);
        const ParamRange& range = entry.signature->params.front();
        if (value && *value >= range.lo && *value <= range.hi) {
          p.values[0] = *value;
          step(p);
        }
      } else {
        for_each_candidate(*entry.signature, t, from, step);
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
  // States are a few words (at least one): a plain loop beats a call to memcpy, and the
  // first word apart spares a one-word state the loop's set-up.
  void copy_state(Word* to, const Word* from) const {
    to[0] = from[0];
    for (std::uint32_t i = 1; i < words_; ++i)
      to[i] = from[i];
  }

  // An action whose one parameter is an id that a `.where` filter admits, read as one run
  // of bits (candidates.hpp): its ids first.. with their fields at fixed places of the
  // state, so that the admitted ids are found without the candidate recursion.
  struct RunFilter {
    FieldRun fields;       // of the ids first..last, in the whole state
    std::uint64_t pattern; // the admitted code in every field
    std::int32_t first;    // the id of the first field
    // One bit (the lowest of its field) per admitted id, in increasing order of ids.
    std::uint64_t admitted(const State& s) const {
      return fields.holding(s.code(fields.bits), pattern);
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
    const std::uint32_t width = b.run->width;
    r.first = static_cast<std::int32_t>(first);
    const auto lo_bit = static_cast<std::uint32_t>((first - b.where_first) * width);
    r.fields = field_run_at(b.base + b.run->bits.offset + lo_bit, width,
                            static_cast<std::uint32_t>(last - first + 1));
    r.pattern = b.run_pattern >> lo_bit;
    return r;
  }

  // Each action's transition, read once: when it is one part at the start of the state
  // that no Fail freezes and that has no choice (most are), its guard and effect are
  // called directly.
  struct Entry {
    std::uint32_t action = 0; // its index in the automaton
    const ActionSignature* signature = nullptr;
    const Transition* transition = nullptr;
    bool input = false; // (a guard that refuses an input is a model error)
    bool simple = false;
    const Guard* guard = nullptr; // null: always enabled
    const Effect* effect = nullptr;
    std::optional<RunFilter> run;   // its candidates, when they come from one run filter
    const Binding* bound = nullptr; // its one parameter's binder, when it has one
  };

  const Automaton* automaton_;
  std::uint32_t words_;
  bool timed_;
  std::vector<Entry> table_;
};

} // namespace tioa
