#pragma once
// A timed I/O automaton (seed 000 §3.1, Def 3.1) over discretised time, written the way
// the papers' figures are: a signature, state variables with initial values, one
// transition per action (precondition + effect), and trajectories (evolve one time
// quantum; stop-when: time cannot pass while it holds).
//
//   Automaton ring("token-ring");
//   auto x = ring.integers("x", n, 0, k - 1);
//   ring.internal("move", {{"i", 1, n - 1}})
//       .pre([=](const State& s, const Params& a) { return s[x[a[0]]] != s[x[a[0] - 1]]; })
//       .eff([=](State& s, const Params& a) { s[x[a[0]]] = s[x[a[0] - 1]]; });
//
// Nondeterminism inside an effect is a `choose(count, effect)`: the effect runs once for
// each choice 0..count-1, each giving its own successor (`choose_where`: only for the
// choices a guard allows).

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "tioa/actions.hpp"
#include "tioa/errors.hpp"
#include "tioa/footprint.hpp"
#include "tioa/start_set.hpp"
#include "tioa/state.hpp"
#include "tioa/transition.hpp"
#include "tioa/variables.hpp"

namespace tioa {

class Automaton;

// Returned by input()/output()/internal() to give the action its transition.
class TransitionBuilder {
public:
  TransitionBuilder(Automaton& automaton, std::size_t action)
      : automaton_(&automaton), action_(action) {}
  TransitionBuilder& pre(Guard precondition);
  TransitionBuilder& eff(Effect effect);
  TransitionBuilder& choose(ChoiceCount count, ChoiceEffect effect);
  TransitionBuilder& choose(std::uint32_t count, ChoiceEffect effect);
  // Choices 0..count-1 of which only those `allowed` gives are steps in a state; the
  // action is enabled where its pre holds and some choice is allowed. For a choice among
  // copies the state holds, one per place (a message pending in any of several slots):
  // choice c reads only place c, so its steps can be told apart without reading the others
  // (the symbolic learner learns the relation choice by choice). Not for inputs, which
  // must be enabled in every state.
  TransitionBuilder& choose_where(std::uint32_t count, ChoiceGuard allowed, ChoiceEffect effect);
  // What the transition may read and write (tioa/footprint.hpp); without it, everything.
  TransitionBuilder& footprint(FootprintFunction footprint);
  // The author's word that the step commutes with a tick of this automaton's time: in
  // every state where both can happen, the step stays possible after the tick, time can
  // still pass after the step, and step-then-tick and tick-then-step (with the same
  // choice) lead to the same state. The zero-time reduction may then leave the step out
  // at a state where time can pass (checker/zero_time_reduction.hpp), and checks the
  // word on every such state.
  TransitionBuilder& commutes_with_time();
  // Binds the parameter named `param` (see Binder); not for inputs, which every value of
  // their box may drive. A ModelError for an unknown parameter or one bound twice.
  TransitionBuilder& bind(const std::string& param, Binder value);
  // The parameter equals the variable (no value while it is ⊥).
  TransitionBuilder& bind(const std::string& param, const Variable<int>& variable);
  // The parameter takes only the ids whose variable in `array` holds `value` (or one of
  // `values`): a conjunct of the guard (Fischer's "loc[p] == REQ", "c[p] >= B"), which
  // .pre may test again or leave out (see Binder). The generator reads one field per id
  // instead of calling the guard for every id. Several filters on one parameter admit
  // the ids all of them admit.
  template <class T>
  TransitionBuilder& where(const std::string& param, const VariableArray<T>& array, T value) {
    return where(param, array, std::vector<T>{value});
  }
  template <class T>
  TransitionBuilder& where(const std::string& param, const VariableArray<T>& array,
                           const std::vector<T>& values) {
    Binding b;
    b.where.reserve(array.size());
    for (const Variable<T>& v : array)
      b.where.push_back(v.slot);
    b.where_first = static_cast<std::int32_t>(array.first);
    std::vector<std::int64_t> codes;
    for (const T& value : values) {
      if constexpr (std::is_same_v<T, bool>)
        codes.push_back(value ? 1 : 0);
      else
        codes.push_back(static_cast<std::int64_t>(value) -
                        (array.size() ? array.items[0].slot.lo : 0));
    }
    return add_filter(param, std::move(b), codes);
  }

private:
  TransitionBuilder& add_binding(const std::string& param, Binding binding);
  TransitionBuilder& add_filter(const std::string& param, Binding binding,
                                const std::vector<std::int64_t>& codes);
  Automaton* automaton_;
  std::size_t action_;
};

class Automaton {
public:
  explicit Automaton(std::string name);

  const std::string& name() const { return name_; }

  // ---- state variables; an initial value of nullopt means "arbitrary at start"
  Variable<bool> boolean(const std::string& name, std::optional<bool> initial);
  Variable<int> integer(const std::string& name, int lo, int hi, std::optional<int> initial);
  // An integer that may be ⊥ (the papers' "x := ⊥"): ⊥ at start unless `initial` is
  // given. Read it only when !s.is_bottom(x); s.set_bottom(x) clears it.
  Variable<int> optional_integer(const std::string& name, int lo, int hi,
                                 std::optional<int> initial = std::nullopt);
  // A clock counted in quanta, saturating at `cap` (read "cap or more"); optionally ⊥.
  Variable<int> clock(const std::string& name, int cap, std::optional<int> initial,
                      bool with_bottom = false);
  template <class E>
  Variable<E> enumeration(const std::string& name, std::vector<std::string> names,
                          std::optional<E> initial) {
    VariableInfo info;
    info.name = name;
    info.kind = VariableKind::enumeration;
    info.hi = static_cast<std::int64_t>(names.size()) - 1;
    info.enum_names = std::move(names);
    if (initial) {
      const auto code = static_cast<std::int64_t>(*initial);
      if (code < 0 || code > info.hi)
        throw ModelError("initial value of '" + name + "' is not one of its " +
                         std::to_string(info.enum_names.size()) + " values");
      info.initial_code = static_cast<std::uint64_t>(code);
    }
    return Variable<E>{declare(std::move(info))};
  }
  // A subset of `elements` (at most 16), e.g. the paper's G_i ⊆ {R1, ..., Rn}: an int
  // bit mask (bit k: elements[k]) shown as "{R1, R3}".
  Variable<int> subset(const std::string& name, std::vector<std::string> elements,
                       std::optional<int> initial);
  // Arrays (maps from ids to variables): `ids` is a count (ids 0..count-1) or ids(a, b).
  VariableArray<bool> booleans(const std::string& name, IdRange ids, std::optional<bool> initial);
  VariableArray<int> integers(const std::string& name, IdRange ids, int lo, int hi,
                              std::optional<int> initial);
  VariableArray<int> clocks(const std::string& name, IdRange ids, int cap,
                            std::optional<int> initial, bool with_bottom = false);
  VariableArray<int> subsets(const std::string& name, IdRange ids,
                             const std::vector<std::string>& elements, std::optional<int> initial);
  template <class E>
  VariableArray<E> enumerations(const std::string& name, IdRange ids,
                                const std::vector<std::string>& names, std::optional<E> initial) {
    VariableArray<E> out;
    out.first = ids.first;
    for (std::size_t i = ids.first; i < ids.first + ids.count; ++i)
      out.items.push_back(enumeration<E>(indexed(name, i), names, initial));
    return out;
  }

  // ---- signature and transitions
  TransitionBuilder input(const std::string& name, std::vector<ParamRange> params = {});
  TransitionBuilder output(const std::string& name, std::vector<ParamRange> params = {});
  TransitionBuilder internal(const std::string& name, std::vector<ParamRange> params = {});

  // ---- trajectories: makes the automaton timed
  void trajectories(Evolve evolve, StatePredicate stop_when = {});

  // ---- facts about every step that a model may declare for the partial-order reduction
  // (checker/zero_time_reduction.hpp); Start, U and hide keep them, compose and Fail
  // build new automata without them.
  //
  // A progress measure: a number that every step strictly increases, from any state (U
  // starts anywhere), so the graph of states has no cycle and every execution ends. Declared by the
  // model (with the argument why in its README), and checked on every step the reduction runs and
  // on every edge of an unreduced stabilisation check: a step that does not increase it is a
  // ModelError.
  void set_progress_measure(StateMeasure measure) { progress_measure_ = std::move(measure); }
  const StateMeasure& progress_measure() const { return progress_measure_; }
  // A halt flag: a boolean that, once true, disables every step (a bound the model met),
  // and that steps only ever set to true. With a progress measure, the reduction leaves
  // it out of what makes two steps depend on each other (a step that may meet the bound
  // would otherwise depend on every other step).
  void set_halt_flag(Variable<bool> flag) { halt_flag_ = flag.slot; }
  const std::optional<Slot>& halt_flag() const { return halt_flag_; }

  // ---- start states (the declared initial values unless set)
  void set_start(StartSet start) { start_ = std::move(start); }
  const StartSet& start() const;

  const StateLayout& layout() const { return layout_; }
  std::uint32_t words() const { return layout_.words(); }
  const std::vector<ActionSignature>& actions() const { return actions_; }
  const std::vector<Transition>& transitions() const { return transitions_; }
  const Trajectories& trajectory() const { return trajectories_; }
  bool timed() const { return trajectories_.timed; }
  std::optional<std::size_t> find_action(const std::string& name) const;
  // Adds to `f` what the step of `action` with `params` may read and write: its declared
  // footprint, or every variable of this automaton.
  void footprint(std::size_t action, const Params& params, Footprint& f) const;

  // ---- used by the operators (compose, Fail, hide) that build automata from automata
  std::size_t add_action(ActionSignature signature, Transition transition);
  Transition& transition(std::size_t action) { return transitions_.at(action); }
  ActionSignature& signature(std::size_t action) { return actions_.at(action); }
  StateLayout& mutable_layout() { return layout_; }
  void set_trajectories(Trajectories t) { trajectories_ = std::move(t); }
  void rename(std::string name) { name_ = std::move(name); }

private:
  Slot declare(VariableInfo info);
  TransitionBuilder declare_action(const std::string& name, ActionKind kind,
                                   std::vector<ParamRange> params);
  static std::string indexed(const std::string& name, std::size_t i) {
    return name + "[" + std::to_string(i) + "]";
  }

  std::string name_;
  StateLayout layout_;
  std::vector<ActionSignature> actions_;
  std::vector<Transition> transitions_;
  Trajectories trajectories_;
  std::optional<StartSet> start_;
  StateMeasure progress_measure_;
  std::optional<Slot> halt_flag_;
  mutable std::optional<StartSet> declared_start_;
};

// The handle of a variable by its name, e.g. "receiver.alive" in a composite; for
// properties written outside the automaton. A ModelError when there is none, or when a
// boolean is asked for a variable that is not one (or the other way round).
template <class T> Variable<T> find_variable(const Automaton& automaton, const std::string& name) {
  const VariableInfo* info = automaton.layout().find(name);
  if (!info)
    throw ModelError(automaton.name() + " has no variable '" + name + "'");
  if (std::is_same_v<T, bool> != (info->kind == VariableKind::boolean))
    throw ModelError("variable '" + name + "' of " + automaton.name() + " is " +
                     (info->kind == VariableKind::boolean ? "" : "not ") + "a boolean");
  return Variable<T>{info->slot()};
}

} // namespace tioa
