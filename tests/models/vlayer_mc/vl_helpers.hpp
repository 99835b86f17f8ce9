#pragma once
// Reading and writing hand-made states of the vlayer_mc automata by variable name, and
// their one-step successors by label ("tick", "GPSupdate_0(4,0)").

#include <climits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tioa/tioa.hpp"

namespace vl_test {

using Words = std::vector<tioa::Word>;
inline constexpr std::int64_t bottom = INT_MIN;

struct Step {
  std::string label;
  Words state;
};

// The first start state the automaton enumerates (the declared one when all are fixed).
inline Words start(const tioa::Automaton& a) {
  Words buffer(a.words() + 1, 0), first;
  a.start().enumerate(buffer.data(), 0, [&] {
    if (first.empty())
      first.assign(buffer.begin(), buffer.begin() + a.words());
  });
  return first;
}

inline const tioa::VariableInfo& info(const tioa::Automaton& a, const std::string& name) {
  const tioa::VariableInfo* v = a.layout().find(name);
  if (!v)
    throw std::logic_error("test: no variable '" + name + "' in " + a.name());
  return *v;
}

// The value of `name`, nullopt for ⊥.
inline std::optional<std::int64_t> get(const tioa::Automaton& a, const Words& s,
                                       const std::string& name) {
  const auto& v = info(a, name);
  const std::uint64_t code = tioa::State(s.data(), 0).code(v.slot());
  if (v.has_bottom && code == v.value_codes())
    return std::nullopt;
  return v.lo + static_cast<std::int64_t>(code);
}

// Sets `name` to `value` (vl_test::bottom for ⊥; booleans as 0/1).
inline void set(const tioa::Automaton& a, Words& s, const std::string& name, std::int64_t value) {
  const auto& v = info(a, name);
  Words padded = s;
  padded.push_back(0);
  tioa::State state(padded.data(), 0);
  if (value == bottom)
    state.set_code(v.slot(), v.value_codes());
  else
    state.set_code(v.slot(), static_cast<std::uint64_t>(value - v.lo));
  padded.pop_back();
  s = padded;
}

inline std::vector<Step> steps(const tioa::Automaton& a, const Words& s) {
  const tioa::SuccessorGenerator generator(a);
  Words from = s, scratch(a.words() + 1, 0);
  from.push_back(0);
  std::vector<Step> out;
  generator.successors(from.data(), scratch.data(),
                       [&](const tioa::Word* to, const tioa::StepLabel& l) {
                         out.push_back({generator.describe(l), Words(to, to + a.words())});
                       });
  return out;
}

// The steps whose label starts with `prefix`.
inline std::vector<Step> only(const std::vector<Step>& all, const std::string& prefix) {
  std::vector<Step> out;
  for (const auto& step : all)
    if (step.label.rfind(prefix, 0) == 0)
      out.push_back(step);
  return out;
}

inline bool has(const std::vector<Step>& all, const std::string& label) {
  for (const auto& step : all)
    if (step.label == label)
      return true;
  return false;
}

// The successor by `label`; throws unless there is exactly one.
inline Words after(const tioa::Automaton& a, const Words& s, const std::string& label) {
  std::optional<Words> found;
  for (auto& step : steps(a, s))
    if (step.label == label) {
      if (found)
        throw std::logic_error("test: two successors labelled " + label);
      found = step.state;
    }
  if (!found)
    throw std::logic_error("test: no successor labelled " + label);
  return *found;
}

} // namespace vl_test
