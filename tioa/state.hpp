#pragma once
// A view on one automaton's part of a packed state. Transitions read and write variables
// through it the way the papers' figures do: `s[loc[p]] = Loc::req`, `if (s[x] == 3)`.

#include <algorithm>
#include <array>
#include <string>
#include <type_traits>

#include "tioa/errors.hpp"
#include "tioa/footprint.hpp"
#include "tioa/variables.hpp"

namespace tioa {

[[noreturn]] void throw_out_of_domain(const Slot& slot, std::int64_t value);
[[noreturn]] void throw_read_of_bottom(const Slot& slot);

class State;

// What `state[variable]` returns: reads convert to T, assignments check the domain.
template <class T> class VariableRef {
public:
  VariableRef(State& state, const Slot& slot) : state_(state), slot_(slot) {}
  operator T() const;
  VariableRef& operator=(T value);
  VariableRef& operator=(const VariableRef& other) { return *this = static_cast<T>(other); }

private:
  State& state_;
  const Slot& slot_;
};

// A state may trace its reads: every bit read through it is then set in `trace` (a mask of
// `trace_words` words, as many as the state has), which tells partial-order reduction what
// a guard looked at (tioa/footprint.hpp). It may trace its writes too, into `write_trace`
// (the bits an effect assigned, whether or not their value changed).
class State {
public:
  State(Word* words, std::uint32_t base, Word* trace = nullptr, std::uint32_t trace_words = 0,
        Word* write_trace = nullptr)
      : words_(words), base_(base), trace_(trace), write_trace_(write_trace),
        trace_words_(trace_words) {}
  State(const Word* words, std::uint32_t base, Word* trace = nullptr, std::uint32_t trace_words = 0)
      : words_(const_cast<Word*>(words)), base_(base), trace_(trace), trace_words_(trace_words) {}

  // The part of this state that belongs to a component placed `offset` bits further on.
  State at(std::uint32_t offset) const {
    return State(words_, base_ + offset, trace_, trace_words_, write_trace_);
  }

  [[gnu::always_inline]] std::uint64_t code(const Slot& slot) const {
    const std::uint32_t bit = base_ + slot.offset;
    if (trace_) [[unlikely]]
      set_bits(trace_, bit, slot.width);
    const std::uint32_t word = bit >> 6, shift = bit & 63;
    std::uint64_t value = words_[word] >> shift;
    if (shift + slot.width > 64) [[unlikely]]
      value |= words_[word + 1] << (64 - shift);
    return value & slot.mask;
  }

  void set_code(const Slot& slot, std::uint64_t code) {
    const std::uint32_t bit = base_ + slot.offset;
    if (write_trace_) [[unlikely]]
      set_bits(write_trace_, bit, slot.width);
    const std::uint32_t word = bit >> 6, shift = bit & 63;
    code &= slot.mask;
    words_[word] = (words_[word] & ~(slot.mask << shift)) | (code << shift);
    if (shift + slot.width > 64) [[unlikely]] {
      const std::uint32_t spill = 64 - shift;
      words_[word + 1] = (words_[word + 1] & ~(slot.mask >> spill)) | (code >> spill);
    }
  }

  template <class T> [[gnu::always_inline]] T get(const Slot& slot) const {
    const std::uint64_t c = code(slot);
    if (slot.has_bottom && c == slot.value_codes) [[unlikely]]
      throw_read_of_bottom(slot);
    if constexpr (std::is_same_v<T, bool>)
      return c != 0;
    else
      return static_cast<T>(static_cast<std::int64_t>(c) + slot.lo);
  }

  template <class T> void set(const Slot& slot, T value) {
    const std::int64_t code = static_cast<std::int64_t>(value) - slot.lo;
    if (code < 0 || static_cast<std::uint64_t>(code) >= slot.value_codes) [[unlikely]]
      throw_out_of_domain(slot, static_cast<std::int64_t>(value));
    set_code(slot, static_cast<std::uint64_t>(code));
  }

  template <class T> [[gnu::always_inline]] T get(const Variable<T>& v) const {
    return get<T>(v.slot);
  }
  template <class T> void set(const Variable<T>& v, T value) { set<T>(v.slot, value); }

  template <class T> [[gnu::always_inline]] bool is_bottom(const Variable<T>& v) const {
    return v.slot.has_bottom && code(v.slot) == v.slot.value_codes;
  }
  template <class T> void set_bottom(const Variable<T>& v) {
    if (!v.slot.has_bottom)
      throw ModelError(std::string("variable '") + v.slot.name + "' has no ⊥");
    set_code(v.slot, v.slot.value_codes);
  }

  // One quantum of time for a clock: +1, saturating at its cap; ⊥ stays ⊥.
  void advance(const Variable<int>& clock) {
    const std::uint64_t c = code(clock.slot);
    if (c + 1 < clock.slot.value_codes)
      set_code(clock.slot, c + 1);
  }

  template <class T> VariableRef<T> operator[](const Variable<T>& v) {
    return VariableRef<T>(*this, v.slot);
  }
  template <class T> [[gnu::always_inline]] T operator[](const Variable<T>& v) const {
    return get<T>(v.slot);
  }

  Word* words() const { return words_; }
  std::uint32_t base() const { return base_; }
  Word* trace() const { return trace_; }

private:
  Word* words_;
  std::uint32_t base_;
  Word* trace_;
  Word* write_trace_ = nullptr;
  std::uint32_t trace_words_;
};

template <class T> VariableRef<T>::operator T() const {
  return state_.template get<T>(slot_);
}

template <class T> VariableRef<T>& VariableRef<T>::operator=(T value) {
  state_.template set<T>(slot_, value);
  return *this;
}

} // namespace tioa
