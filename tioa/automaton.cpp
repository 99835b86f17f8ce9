#include "tioa/automaton.hpp"

#include <algorithm>

#include "tioa/errors.hpp"

namespace tioa {

TransitionBuilder& TransitionBuilder::pre(Guard precondition) {
  automaton_->transition(action_).parts.front().guard = std::move(precondition);
  return *this;
}

TransitionBuilder& TransitionBuilder::eff(Effect effect) {
  automaton_->transition(action_).parts.front().effect = std::move(effect);
  return *this;
}

TransitionBuilder& TransitionBuilder::choose(ChoiceCount count, ChoiceEffect effect) {
  TransitionPart& part = automaton_->transition(action_).parts.front();
  part.choices = std::move(count);
  part.choice_effect = std::move(effect);
  return *this;
}

TransitionBuilder& TransitionBuilder::choose(std::uint32_t count, ChoiceEffect effect) {
  return choose([count](const State&, const Params&) { return count; }, std::move(effect));
}

TransitionBuilder& TransitionBuilder::choose_where(std::uint32_t count, ChoiceGuard allowed,
                                                   ChoiceEffect effect) {
  const ActionSignature& sig = automaton_->signature(action_);
  if (sig.kind == ActionKind::input)
    throw ModelError("input '" + sig.name +
                     "' cannot choose_where: an input is enabled in every state");
  if (count == 0)
    throw ModelError("action '" + sig.name + "': choose_where over no choice");
  choose(count, std::move(effect));
  TransitionPart& part = automaton_->transition(action_).parts.front();
  part.choice_allowed = std::move(allowed);
  part.choice_limit = count;
  return *this;
}

TransitionBuilder& TransitionBuilder::footprint(FootprintFunction footprint) {
  automaton_->transition(action_).parts.front().footprint = std::move(footprint);
  return *this;
}

TransitionBuilder& TransitionBuilder::commutes_with_time() {
  automaton_->transition(action_).parts.front().commutes_with_time = true;
  return *this;
}

TransitionBuilder& TransitionBuilder::bind(const std::string& param, Binder value) {
  Binding b;
  b.value = std::move(value);
  return add_binding(param, std::move(b));
}

TransitionBuilder& TransitionBuilder::add_filter(const std::string& param, Binding binding,
                                                 const std::vector<std::int64_t>& codes) {
  const ActionSignature& sig = automaton_->signature(action_);
  if (binding.where.empty())
    throw ModelError("action '" + sig.name + "': parameter '" + param +
                     "' is filtered by an empty array");
  if (codes.empty())
    throw ModelError("action '" + sig.name + "': parameter '" + param +
                     "' is filtered by an empty set of values");
  for (const std::int64_t code : codes) {
    for (const Slot& slot : binding.where)
      if (code < 0 || static_cast<std::uint64_t>(code) >= slot.value_codes)
        throw ModelError("action '" + sig.name + "': parameter '" + param +
                         "' is filtered by a value outside the domain of '" + slot.name + "'");
    const auto admitted = static_cast<std::uint64_t>(code);
    if (std::find(binding.where_codes.begin(), binding.where_codes.end(), admitted) ==
        binding.where_codes.end())
      binding.where_codes.push_back(admitted);
  }
  binding.run = field_run(binding.where);
  if (binding.run)
    for (const std::uint64_t code : binding.where_codes)
      binding.run_patterns.push_back(binding.run->pattern(code));
  return add_binding(param, std::move(binding));
}

TransitionBuilder& TransitionBuilder::add_binding(const std::string& param, Binding binding) {
  const ActionSignature& sig = automaton_->signature(action_);
  if (sig.kind == ActionKind::input)
    throw ModelError("input '" + sig.name + "' cannot bind a parameter: every value may occur");
  std::size_t index = 0;
  while (index < sig.params.size() && sig.params[index].name != param)
    ++index;
  if (index == sig.params.size())
    throw ModelError("action '" + sig.name + "' has no parameter '" + param + "' to bind");
  Transition& t = automaton_->transition(action_);
  // Filters add up (the ids all of them admit); a binder gives the one value, alone.
  for (const Binding& b : t.bindings)
    if (b.param == index && !(b.filter() && binding.filter()))
      throw ModelError("parameter '" + param + "' of '" + sig.name + "' is bound twice");
  binding.param = static_cast<std::uint8_t>(index);
  t.bindings.push_back(std::move(binding));
  // By parameter; a parameter's filters in the order they were given.
  std::stable_sort(t.bindings.begin(), t.bindings.end(),
                   [](const Binding& a, const Binding& b) { return a.param < b.param; });
  return *this;
}

TransitionBuilder& TransitionBuilder::bind(const std::string& param,
                                           const Variable<int>& variable) {
  return bind(param, [variable](const State& s, const Params&) -> std::optional<std::int32_t> {
    if (s.is_bottom(variable))
      return std::nullopt;
    return s[variable];
  });
}

void Automaton::footprint(std::size_t action, const Params& params, Footprint& f) const {
  transitions_.at(action).add_footprint(params, f, layout_.bits());
}

Automaton::Automaton(std::string name) : name_(std::move(name)) {
  if (name_.empty())
    throw ModelError("an automaton needs a name");
}

Slot Automaton::declare(VariableInfo info) {
  declared_start_.reset();
  return layout_.add(std::move(info)).slot();
}

Variable<bool> Automaton::boolean(const std::string& name, std::optional<bool> initial) {
  VariableInfo info;
  info.name = name;
  info.kind = VariableKind::boolean;
  info.hi = 1;
  if (initial)
    info.initial_code = *initial ? 1 : 0;
  return Variable<bool>{declare(std::move(info))};
}

Variable<int> Automaton::integer(const std::string& name, int lo, int hi,
                                 std::optional<int> initial) {
  VariableInfo info;
  info.name = name;
  info.lo = lo;
  info.hi = hi;
  if (initial) {
    if (*initial < lo || *initial > hi)
      throw ModelError("initial value of '" + name + "' is outside " + std::to_string(lo) + ".." +
                       std::to_string(hi));
    info.initial_code = static_cast<std::uint64_t>(*initial - lo);
  }
  return Variable<int>{declare(std::move(info))};
}

Variable<int> Automaton::optional_integer(const std::string& name, int lo, int hi,
                                          std::optional<int> initial) {
  VariableInfo info;
  info.name = name;
  info.lo = lo;
  info.hi = hi;
  info.has_bottom = true;
  if (initial && (*initial < lo || *initial > hi))
    throw ModelError("initial value of '" + name + "' is outside " + std::to_string(lo) + ".." +
                     std::to_string(hi));
  info.initial_code = initial ? static_cast<std::uint64_t>(*initial - lo) : info.value_codes();
  return Variable<int>{declare(std::move(info))};
}

Variable<int> Automaton::subset(const std::string& name, std::vector<std::string> elements,
                                std::optional<int> initial) {
  if (elements.empty() || elements.size() > 16)
    throw ModelError("set '" + name + "' needs 1..16 elements");
  VariableInfo info;
  info.name = name;
  info.kind = VariableKind::set;
  info.hi = (1 << elements.size()) - 1;
  info.enum_names = std::move(elements);
  if (initial) {
    if (*initial < 0 || *initial > info.hi)
      throw ModelError("initial value of set '" + name + "' is not a subset of its elements");
    info.initial_code = static_cast<std::uint64_t>(*initial);
  }
  return Variable<int>{declare(std::move(info))};
}

VariableArray<int> Automaton::subsets(const std::string& name, IdRange ids,
                                      const std::vector<std::string>& elements,
                                      std::optional<int> initial) {
  VariableArray<int> out;
  out.first = ids.first;
  for (std::size_t i = ids.first; i < ids.first + ids.count; ++i)
    out.items.push_back(subset(indexed(name, i), elements, initial));
  return out;
}

Variable<int> Automaton::clock(const std::string& name, int cap, std::optional<int> initial,
                               bool with_bottom) {
  if (cap < 0)
    throw ModelError("clock '" + name + "' needs a cap of at least 0");
  VariableInfo info;
  info.name = name;
  info.kind = VariableKind::clock;
  info.hi = cap;
  info.has_bottom = with_bottom;
  if (initial) {
    if (*initial < 0 || *initial > cap)
      throw ModelError("initial value of clock '" + name + "' is outside 0.." +
                       std::to_string(cap));
    info.initial_code = static_cast<std::uint64_t>(*initial);
  }
  return Variable<int>{declare(std::move(info))};
}

VariableArray<bool> Automaton::booleans(const std::string& name, IdRange ids,
                                        std::optional<bool> initial) {
  VariableArray<bool> out;
  out.first = ids.first;
  for (std::size_t i = ids.first; i < ids.first + ids.count; ++i)
    out.items.push_back(boolean(indexed(name, i), initial));
  return out;
}

VariableArray<int> Automaton::integers(const std::string& name, IdRange ids, int lo, int hi,
                                       std::optional<int> initial) {
  VariableArray<int> out;
  out.first = ids.first;
  for (std::size_t i = ids.first; i < ids.first + ids.count; ++i)
    out.items.push_back(integer(indexed(name, i), lo, hi, initial));
  return out;
}

VariableArray<int> Automaton::clocks(const std::string& name, IdRange ids, int cap,
                                     std::optional<int> initial, bool with_bottom) {
  VariableArray<int> out;
  out.first = ids.first;
  for (std::size_t i = ids.first; i < ids.first + ids.count; ++i)
    out.items.push_back(clock(indexed(name, i), cap, initial, with_bottom));
  return out;
}

TransitionBuilder Automaton::declare_action(const std::string& name, ActionKind kind,
                                            std::vector<ParamRange> params) {
  if (params.size() > max_params)
    throw ModelError("action '" + name + "' has more than " + std::to_string(max_params) +
                     " parameters");
  for (const auto& existing : actions_)
    if (existing.name == name)
      throw ModelError("action '" + name + "' is declared twice in " + name_);
  Transition t;
  t.input = t.parts.front().input = kind == ActionKind::input;
  return TransitionBuilder(
      *this, add_action(ActionSignature(name, kind, std::move(params)), std::move(t)));
}

TransitionBuilder Automaton::input(const std::string& name, std::vector<ParamRange> params) {
  return declare_action(name, ActionKind::input, std::move(params));
}
TransitionBuilder Automaton::output(const std::string& name, std::vector<ParamRange> params) {
  return declare_action(name, ActionKind::output, std::move(params));
}
TransitionBuilder Automaton::internal(const std::string& name, std::vector<ParamRange> params) {
  return declare_action(name, ActionKind::internal, std::move(params));
}

std::size_t Automaton::add_action(ActionSignature signature, Transition transition) {
  actions_.push_back(std::move(signature));
  transitions_.push_back(std::move(transition));
  return actions_.size() - 1;
}

void Automaton::trajectories(Evolve evolve, StatePredicate stop_when) {
  trajectories_ = Trajectories{
      true,
      {TrajectoryPart{std::move(evolve), std::move(stop_when), 0, {}, TransitionPart::own_state}}};
}

const StartSet& Automaton::start() const {
  if (start_)
    return *start_;
  if (!declared_start_)
    declared_start_ = StartSet::declared(layout_);
  return *declared_start_;
}

std::optional<std::size_t> Automaton::find_action(const std::string& name) const {
  for (std::size_t i = 0; i < actions_.size(); ++i)
    if (actions_[i].name == name)
      return i;
  return std::nullopt;
}

} // namespace tioa
