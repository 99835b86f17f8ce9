#pragma once
// Small helpers shared by the tests of the DSL: states as plain word vectors, start sets
// and successors as ordinary containers, and the message of an expected ModelError.

#include <deque>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "tioa/tioa.hpp"

namespace tioa_test {

using tioa::Word;
using Words = std::vector<Word>;

// A zeroed buffer for one state of `a`, with the spare word the DSL's enumerators expect.
inline Words blank(const tioa::Automaton& a) {
  return Words(a.words() + 1, 0);
}

// The first words() words of a buffer: the state itself.
inline Words trimmed(const Word* words, std::uint32_t count) {
  return Words(words, words + count);
}

// `width` bits of `w` from bit `offset`, read bit by bit (independent of State).
inline std::uint64_t bits_at(const Word* w, std::uint32_t offset, std::uint32_t width) {
  std::uint64_t out = 0;
  for (std::uint32_t i = 0; i < width; ++i)
    out |= ((w[(offset + i) / 64] >> ((offset + i) % 64)) & 1) << i;
  return out;
}
inline std::uint64_t bits_at(const Words& w, std::uint32_t offset, std::uint32_t width) {
  return bits_at(w.data(), offset, width);
}

// Every state a start set visits, in order, each `words` words long (duplicates kept).
inline std::vector<Words> enumerate(const tioa::StartSet& start, std::uint32_t words,
                                    std::uint32_t base = 0) {
  std::vector<Words> out;
  Words buffer(words + 2, 0);
  start.enumerate(buffer.data(), base, [&] { out.push_back(trimmed(buffer.data(), words)); });
  return out;
}

inline std::vector<Words> start_states(const tioa::Automaton& a) {
  return enumerate(a.start(), a.words());
}

inline std::set<Words> start_set(const tioa::Automaton& a) {
  const auto list = start_states(a);
  return std::set<Words>(list.begin(), list.end());
}

// One step of the one-step semantics: its label as the generator describes it and the
// successor state.
struct Step {
  std::string label;
  Words state;
  bool tick = false;
  std::uint32_t duration = 0;

  bool operator<(const Step& other) const {
    return std::tie(label, state) < std::tie(other.label, other.state);
  }
  bool operator==(const Step& other) const { return label == other.label && state == other.state; }
};

inline std::vector<Step> steps(const tioa::Automaton& a, const Words& from) {
  const tioa::SuccessorGenerator generator(a);
  Words state = from;
  state.resize(a.words() + 1, 0);
  Words scratch(a.words() + 1, 0);
  std::vector<Step> out;
  const std::size_t count = generator.successors(
      state.data(), scratch.data(), [&](const Word* to, const tioa::StepLabel& l) {
        out.push_back(Step{generator.describe(l), trimmed(to, a.words()), l.is_tick(),
                           generator.duration(l)});
      });
  // The generator's count and the calls it made agree.
  if (count != out.size())
    out.push_back(Step{"<count mismatch>", {}, false, 0});
  return out;
}

// The successors reached by the steps with this exact label, in order.
inline std::vector<Words> after(const tioa::Automaton& a, const Words& from,
                                const std::string& label) {
  std::vector<Words> out;
  for (const auto& s : steps(a, from))
    if (s.label == label)
      out.push_back(s.state);
  return out;
}

inline std::vector<std::string> labels(const std::vector<Step>& list) {
  std::vector<std::string> out;
  for (const auto& s : list)
    out.push_back(s.label);
  return out;
}

// The reachable part of `a` by a plain breadth-first search, independent of checker/:
// its states and its transitions (from, label, to).
struct Reachable {
  std::set<Words> states;
  std::set<std::tuple<Words, std::string, Words>> transitions;
};

inline Reachable reachable(const tioa::Automaton& a) {
  Reachable out;
  std::deque<Words> todo;
  for (const auto& s : start_states(a))
    if (out.states.insert(s).second)
      todo.push_back(s);
  while (!todo.empty()) {
    const Words from = todo.front();
    todo.pop_front();
    for (const auto& step : steps(a, from)) {
      out.transitions.emplace(from, step.label, step.state);
      if (out.states.insert(step.state).second)
        todo.push_back(step.state);
    }
  }
  return out;
}

// prefix + i + suffix, built by appending (GCC 12 warns falsely, -Wrestrict, on
// "literal" + std::to_string(i) at -O2).
inline std::string numbered(const std::string& prefix, int i, const std::string& suffix = "") {
  std::string out = prefix;
  out.append(std::to_string(i));
  out.append(suffix);
  return out;
}

// A handle on a variable of `a` found by its (possibly prefixed) name.
template <class T> tioa::Variable<T> variable(const tioa::Automaton& a, const std::string& name) {
  const tioa::VariableInfo* info = a.layout().find(name);
  if (!info)
    throw std::logic_error("test: no variable '" + name + "' in " + a.name());
  return tioa::Variable<T>{info->slot()};
}

// A read-only view of a state.
inline tioa::State view(const Words& w) {
  return tioa::State(w.data(), 0);
}

template <class T> T value_of(const Words& w, const tioa::Variable<T>& v) {
  return view(w).get(v);
}

// The message of the ModelError that f throws, or a marker when it throws none. Other
// exceptions propagate and fail the test.
template <class F> std::string model_error(F&& f) {
  try {
    f();
  } catch (const tioa::ModelError& e) {
    return e.what();
  }
  return "<no ModelError>";
}

} // namespace tioa_test
