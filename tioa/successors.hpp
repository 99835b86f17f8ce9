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
          if (!t.choice_allowed(from, p, c))
            continue;
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
        for (std::uint64_t match = run.admitted(state); match != 0; match &= match - 1) {
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

  // An action whose one parameter is an id that `.where` filters admit, each read as one
  // run of bits of one width (candidates.hpp): its ids first.. with their fields at fixed
  // places of the state, so that the admitted ids are found without the candidate
  // recursion.
  struct RunFilter {
    static constexpr std::uint32_t max_filters = 4, max_codes = 4;
    struct Filter {
      // The fields of the ids first..last: `mask` bits from bit `shift` of word `word`,
      // spilling into the next word when `spans`.
      std::uint32_t word = 0, shift = 0;
      bool spans = false;
      std::uint64_t mask = 0;
      std::uint32_t codes = 0;
      std::uint64_t patterns[max_codes] = {}; // each admitted code in every field
      std::uint64_t read(const Word* state) const {
        std::uint64_t value = state[word] >> shift;
        if (spans)
          value |= state[word + 1] << (64 - shift);
        return value & mask;
      }
    };
    FieldRun fields;    // the shape of every filter's fields: width, low bits, field_of
    std::int32_t first; // the id of the first field
    std::uint32_t count = 0;
    Filter filters[max_filters];
    // One bit (the lowest of its field) per id every filter admits, in increasing order.
    std::uint64_t admitted(const Word* state) const {
      if (count == 1 && filters[0].codes == 1) // one filter of one code, as most are
        return fields.holding(filters[0].read(state), filters[0].patterns[0]);
      std::uint64_t match = ~std::uint64_t{0};
      for (std::uint32_t f = 0; f < count; ++f) {
        const Filter& filter = filters[f];
        const std::uint64_t code = filter.read(state);
        std::uint64_t admitted_here = 0;
        for (std::uint32_t c = 0; c < filter.codes; ++c)
          admitted_here |= ~fields.differing(code ^ filter.patterns[c]);
        match &= admitted_here;
      }
      return match & fields.low;
    }
  };
  static std::optional<RunFilter> run_filter(const ActionSignature& sig, const Transition& t) {
    if (sig.params.size() != 1 || sig.accepts || t.bindings.empty() ||
        t.bindings.size() > RunFilter::max_filters)
      return std::nullopt;
    const ParamRange& range = sig.params.front();
    std::int64_t first = range.lo, last = range.hi;
    for (const Binding& b : t.bindings) {
      if (b.param != 0 || !b.filter() || !b.run || b.run->width != t.bindings.front().run->width ||
          b.run_patterns.size() > RunFilter::max_codes)
        return std::nullopt;
      first = std::max<std::int64_t>(first, b.where_first);
      last = std::min<std::int64_t>(last, b.where_first + std::int64_t(b.where.size()) - 1);
    }
    if (first > last)
      return std::nullopt; // (no id: the recursion returns at once too)
    RunFilter r;
    const std::uint32_t width = t.bindings.front().run->width;
    const auto count = static_cast<std::uint32_t>(last - first + 1);
    r.first = static_cast<std::int32_t>(first);
    for (const Binding& b : t.bindings) {
      const auto lo_bit = static_cast<std::uint32_t>((first - b.where_first) * width);
      RunFilter::Filter& f = r.filters[r.count++];
      const std::uint32_t bit = b.base + b.run->bits.offset + lo_bit;
      f.word = bit / 64;
      f.shift = bit % 64;
      f.spans = f.shift + count * width > 64;
      f.mask = (std::uint64_t{1} << (count * width)) - 1; // (count * width < 64)
      for (const std::uint64_t pattern : b.run_patterns)
        f.patterns[f.codes++] = pattern >> lo_bit;
    }
    r.fields = field_run_at(0, width, count);
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
