#pragma once
// One action's transition and an automaton's trajectories, lowered into flat parts (issue
// 14). A part is what one automaton's author wrote (TransitionBuilder: guard, effect,
// footprint), placed where that automaton's state lives in the automaton that runs it.
// A transition written with TransitionBuilder has one part; compose (compose.hpp) joins
// the owner's parts with the parts of every input the action drives, each filtered by its
// input's box; Fail (fail.hpp) adds its `failed` flag to every part of A, so a failed part
// is a bit test. However deep the construction, a step is then one loop over the authors'
// guards and effects, with no wrapper around them.
//
// Decision (issue 14 asks for guard and effect "fused"): they stay two calls, each the
// author's own, in one entry. A fused call would save one call per enabled step, while
// most calls are guards that fail, and partial-order reduction runs guards alone.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "tioa/actions.hpp"
#include "tioa/field_run.hpp"
#include "tioa/footprint.hpp"
#include "tioa/start_set.hpp"
#include "tioa/state.hpp"

namespace tioa {

using Guard = std::function<bool(const State&, const Params&)>;
using Effect = std::function<void(State&, const Params&)>;
using ChoiceCount = std::function<std::uint32_t(const State&, const Params&)>;
using ChoiceEffect = std::function<void(State&, const Params&, std::uint32_t choice)>;
using ChoiceGuard = std::function<bool(const State&, const Params&, std::uint32_t choice)>;
using Evolve = std::function<void(State&)>;
using StateMeasure = std::function<std::uint64_t(const State&)>;

// A binder gives the only value a parameter can take for the step to be enabled in a
// state (nullopt: none, e.g. the variable is ⊥): the one-point rule of a guard that says
// "this parameter equals that state value" (e.g. GPSupdate(l, t)_p with l = loc(p)). The
// successor generator then tries that value instead of every value of the box. A binder
// reads the state and the parameters before its own. A step is enabled when each bound
// parameter has its binder's value or is admitted by its filters, and the guard holds:
// the guard may test the same again (most do, as the paper's line reads) or leave it out
// (Fischer's set(p): its filter `loc[p] == REQ` is the whole guard).
using Binder = std::function<std::optional<std::int32_t>(const State&, const Params&)>;

// A parameter bound to the state: one value (`value`, a Binder), or, when `value` is
// empty, a filter: the ids whose variable in an array holds one of a few values (the
// guard's "loc[p] == REQ" or "c[p] >= B", TransitionBuilder::where), tested by reading one
// field per id inline instead of calling the guard through a std::function. A parameter
// may have several filters (the ids every one admits), or one binder.
struct Binding {
  std::uint8_t param = 0;
  Binder value;
  std::vector<Slot> where;      // (a filter) the array's variables, by id from where_first
  std::int32_t where_first = 0; // the id of where[0]
  // The codes the variable of an admitted id may hold (a filter has at least one).
  std::vector<std::uint64_t> where_codes;
  std::uint32_t base = 0; // where the state of the automaton that wrote it begins
  // (a filter whose variables lie one after the other, all as wide, in at most 63 bits, as
  // an array of small variables declared together does) The run of bits they fill, and
  // each admitted code in every field of it: the generator reads every id's field at once.
  std::optional<FieldRun> run;
  std::vector<std::uint64_t> run_patterns;

  bool filter() const { return !value; }
  // (a one-point binder) Its value in this state.
  std::optional<std::int32_t> bind(const State& s, const Params& p) const {
    return value(base ? s.at(base) : s, p);
  }
  // (a filter) Whether `id` is admitted in `local`, the state of the automaton that wrote
  // it (an id outside the array never is: the guard could not read its variable).
  bool admits(const State& local, std::int32_t id) const {
    const std::int64_t i = std::int64_t{id} - where_first;
    if (i < 0 || i >= static_cast<std::int64_t>(where.size()))
      return false;
    const std::uint64_t code = local.code(where[static_cast<std::size_t>(i)]);
    for (const std::uint64_t admitted : where_codes)
      if (code == admitted)
        return true;
    return false;
  }
  // (a filter with a run) One bit, the lowest of its field, per field of `run_code` (the
  // fields of `run`, or a part of them from field 0, shifted down by `lo_bit` bits) that
  // holds an admitted code.
  std::uint64_t admitted_in(std::uint64_t run_code, std::uint64_t low, std::uint32_t lo_bit) const {
    std::uint64_t match = 0;
    for (const std::uint64_t pattern : run_patterns)
      match |= ~run->differing(run_code ^ (pattern >> lo_bit));
    return match & low;
  }
  // Whether the value `p` gives the parameter is one the binding allows in `s`.
  bool allows(const State& s, const Params& p) const {
    if (filter())
      return admits(base ? s.at(base) : s, p[param]);
    const std::optional<std::int32_t> v = bind(s, p);
    return v && *v == p[param];
  }
};

// Whether one of the `failed` flags of the Fail()s around a part is set.
inline bool any_set(const std::vector<Slot>& flags, const State& s) {
  for (const Slot& flag : flags)
    if (s.code(flag) != 0)
      return true;
  return false;
}

// One automaton's share of a step.
struct TransitionPart {
  // Its automaton's whole state, whatever its size once placed (the default footprint).
  static constexpr std::uint32_t own_state = 0xffffffffu;

  Guard guard;                // empty: always enabled
  Effect effect;              // deterministic effect (empty: no change), or
  ChoiceEffect choice_effect; // one effect per choice, with
  ChoiceCount choices;        // the number of choices in this state (empty: 1)
  // (an owner's choose_where) The choices that are steps in a state, of `choice_limit`.
  ChoiceGuard choice_allowed;
  std::uint32_t choice_limit = 1;
  FootprintFunction footprint; // what it may read and write (empty: `bits` from `base`)
  std::uint32_t base = 0;      // where its automaton's state begins
  std::uint32_t bits = own_state;
  // The `failed` flags of the Fail()s around its automaton: while one is set the part
  // does nothing (and, as the owner of an output or internal action, is disabled).
  std::vector<Slot> frozen_by;
  // Receiving an input of a composition: it takes part only in the occurrences that are
  // in every box (the first: its own action's signature, which names it in errors).
  std::vector<std::shared_ptr<const ActionSignature>> boxes;
  bool input = false;    // its own action is an input: it may not refuse an occurrence
  std::string component; // the component it belongs to (errors), empty at the top
  // Its author's word that the part commutes with a tick of its automaton's time
  // (TransitionBuilder::commutes_with_time).
  bool commutes_with_time = false;

  bool frozen(const State& s) const { return any_set(frozen_by, s); }
  bool receives(const Params& p) const {
    for (const auto& box : boxes)
      if (!box->contains(p))
        return false;
    return true;
  }
  State local(const State& s) const { return base ? s.at(base) : s; }
  // Runs nothing and touches nothing (the owner of an input the environment drives).
  bool idle() const {
    return !guard && !effect && !choice_effect && !footprint && bits == 0 && frozen_by.empty();
  }
};

// The transition of one action: parts[0] is the owner, whose guard says when the action
// is enabled; the others receive it (compose), in the order their choices are numbered.
struct Transition {
  std::vector<TransitionPart> parts = std::vector<TransitionPart>(1);
  std::vector<Binding> bindings; // parameters bound to state values (none: the whole box)
  bool input = false;            // the action is an input: a frozen owner takes it, doing nothing

  // Whether the action has a step: the owner's guard holds (or it is a frozen input) and,
  // for a choose_where, one of its choices is allowed.
  bool enabled(const State& s, const Params& p) const {
    if (!guard_holds(s, p))
      return false;
    const TransitionPart& owner = parts.front();
    if (!owner.choice_allowed)
      return true;
    for (std::uint32_t c = 0; c < owner.choice_limit; ++c)
      if (owner.choice_allowed(owner.local(s), p, c))
        return true;
    return false;
  }
  // The owner's guard alone (its choices not asked).
  bool guard_holds(const State& s, const Params& p) const {
    const TransitionPart& owner = parts.front();
    if (!owner.frozen_by.empty() && owner.frozen(s))
      return input;
    if (!owner.guard)
      return true;
    return owner.base == 0 ? owner.guard(s, p) : owner.guard(s.at(owner.base), p);
  }
  // Whether choice `choice` (of choice_count) is a step, in a state where the action is
  // enabled: the owner's part of it is allowed (choose_where; the owner's choice is the
  // lowest digit, see apply).
  bool choice_allowed(const State& s, const Params& p, std::uint32_t choice) const {
    const TransitionPart& owner = parts.front();
    return !owner.choice_allowed ||
           owner.choice_allowed(owner.local(s), p, choice % owner.choice_limit);
  }
  // The choices of the owner's choose_where (1: none).
  std::uint32_t owner_choices() const { return parts.front().choice_limit; }
  // The product of the choices of the parts that take part (mixed radix, in part order).
  std::uint32_t choice_count(const State& s, const Params& p) const {
    std::uint32_t count = 1;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const TransitionPart& part = parts[i];
      if (part.choices && (i == 0 || part.receives(p)) && !part.frozen(s))
        count *= part.choices(part.local(s), p);
    }
    return count;
  }
  // Runs every part that takes part, in order; a receiving input that is not enabled is a
  // ModelError (TIOA are input-enabled). A part's choice count is read before its effect
  // runs, on its own state, which the parts before it do not touch.
  void apply(State& s, const Params& p, std::uint32_t choice) const {
    const TransitionPart& owner = parts.front();
    if (parts.size() > 1 || !owner.frozen_by.empty()) {
      apply_parts(s, p, choice);
      return;
    }
    // One author's transition, as most are: its own effect.
    State local = owner.local(s);
    if (owner.choice_effect)
      owner.choice_effect(local, p, choice);
    else if (owner.effect)
      owner.effect(local, p);
  }
  // Whether every part that takes part in some occurrence declares that it commutes with
  // a tick (TransitionBuilder::commutes_with_time); the environment's idle part of an
  // input counts as declaring it. False for a transition with no part.
  bool commutes_with_time() const {
    bool any = false;
    for (const TransitionPart& part : parts) {
      if (part.idle())
        continue;
      if (!part.commutes_with_time)
        return false;
      any = true;
    }
    return any;
  }
  // Adds to `f` what the step may read and write; `own_bits`: the state size of the
  // automaton that runs it (the footprint of a part that declares none, at the top).
  void add_footprint(const Params& p, Footprint& f, std::uint32_t own_bits) const;
  // The same transition as seen from an automaton where this one's state begins at
  // `base`, its default footprint `bits` wide; `box` (non-null): it receives only the
  // occurrences in that box.
  Transition placed(std::uint32_t base, std::uint32_t bits,
                    const std::shared_ptr<const ActionSignature>& box,
                    const std::string& component) const;

private:
  void apply_parts(State& s, const Params& p, std::uint32_t choice) const;
};

// One automaton's share of time passing.
struct TrajectoryPart {
  Evolve evolve;            // the state one quantum later (empty: nothing changes)
  StatePredicate stop_when; // time cannot pass while this holds (empty: never)
  std::uint32_t base = 0;
  std::vector<Slot> frozen_by; // as TransitionPart: a failed part lets time pass, unchanged
  // The width of its automaton's state, from `base` (TransitionPart::own_state: the
  // automaton's whole state, at the top): all that its evolve and stop_when may touch.
  std::uint32_t bits = TransitionPart::own_state;
};

// Trajectories over discretised time: one tick is one quantum. Time passes when no part
// stops it, and then every part evolves.
struct Trajectories {
  bool timed = false;
  std::vector<TrajectoryPart> parts;

  void evolve(State& s) const {
    if (parts.size() == 1 && parts.front().frozen_by.empty() && parts.front().base == 0) {
      if (parts.front().evolve)
        parts.front().evolve(s);
      return;
    }
    evolve_parts(s);
  }
  // Whether some part may ever stop time.
  bool can_stop() const;
  // Whether time cannot pass in `s`. Traced (a State with a trace), it traces only the
  // part that stops time: what the parts before it read did not decide that.
  bool stops(const State& s) const {
    if (parts.size() == 1 && parts.front().frozen_by.empty() && parts.front().base == 0)
      return parts.front().stop_when && parts.front().stop_when(s);
    return stops_parts(s);
  }
  // Places them where a component's state begins (compose), `bits` wide.
  void place(std::uint32_t base, std::uint32_t bits);
  // Sets in `mask` every bit time may read or change: each part's automaton's state and
  // the flags that freeze it; `own_bits`: the state size at the top.
  void footprint(Word* mask, std::uint32_t own_bits) const;

private:
  void evolve_parts(State& s) const;
  bool stops_parts(const State& s) const;
};

} // namespace tioa
