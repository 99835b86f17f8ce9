#pragma once
// {p | a[p] ∈ values}: the ids of an array of variables whose variable holds one of a few
// values, for the predicates, trajectories and stop-when conditions that quantify over an
// array as the papers' figures do ("at most one process is in CS", "no process in REQ has
// c[p] ≥ A"). Made once when the model is built, read in every state:
//
//   const tioa::IdsWhere<Loc> in_cs(loc, {Loc::cs});
//   ... [=](const State& s) { return in_cs.count(s) <= 1; }
//
// When the array's variables lie side by side (as an array of small variables declared
// together does), share their lowest value and have no ⊥, one read of the state gives
// every id at once (field_run.hpp); otherwise each variable is read in turn, exactly as
// s[a[p]] would be (a read of ⊥ then throws as it does there). Either way the same ids,
// in increasing order.

#include <bit>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "tioa/errors.hpp"
#include "tioa/field_run.hpp"
#include "tioa/state.hpp"
#include "tioa/variables.hpp"

namespace tioa {

template <class T> class IdsWhere {
public:
  IdsWhere(const VariableArray<T>& array, std::initializer_list<T> values)
      : values_(values), first_(array.first) {
    if (values_.empty())
      throw ModelError("an id query needs at least one value");
    bool has_bottom = false, same_domain = true; // (one pattern per value for the run)
    for (const Variable<T>& v : array) {
      slots_.push_back(v.slot);
      has_bottom = has_bottom || v.slot.has_bottom;
      same_domain = same_domain && v.slot.lo == slots_.front().lo;
      for (const T value : values_) {
        const std::int64_t code = static_cast<std::int64_t>(value) - v.slot.lo;
        if (code < 0 || static_cast<std::uint64_t>(code) >= v.slot.value_codes)
          throw ModelError(std::string("an id query asks for a value outside the domain of '") +
                           v.slot.name + "'");
      }
    }
    if (!has_bottom && same_domain)
      run_ = field_run(slots_);
    if (run_)
      for (const T value : values_)
        patterns_.push_back(run_->pattern(
            static_cast<std::uint64_t>(static_cast<std::int64_t>(value) - slots_.front().lo)));
  }

  // Calls visit(id) for each id whose variable holds one of the values, in increasing order.
  template <class Visit> void for_each(const State& s, Visit&& visit) const {
    if (run_) {
      for (std::uint64_t m = matches(s); m != 0; m &= m - 1)
        visit(first_ + run_->field_of(static_cast<std::uint32_t>(std::countr_zero(m))));
      return;
    }
    for (std::size_t i = 0; i < slots_.size(); ++i)
      if (holds(s, i))
        visit(first_ + i);
  }

  // Whether test(id) holds for one of those ids (tried in increasing order, up to the first).
  template <class Test> bool any(const State& s, Test&& test) const {
    if (run_) {
      for (std::uint64_t m = matches(s); m != 0; m &= m - 1)
        if (test(first_ + run_->field_of(static_cast<std::uint32_t>(std::countr_zero(m)))))
          return true;
      return false;
    }
    for (std::size_t i = 0; i < slots_.size(); ++i)
      if (holds(s, i) && test(first_ + i))
        return true;
    return false;
  }

  // How many ids' variables hold one of the values.
  std::size_t count(const State& s) const {
    std::size_t n = 0;
    if (run_) { // (a loop: std::popcount is a library call on the baseline x86-64)
      for (std::uint64_t m = matches(s); m != 0; m &= m - 1)
        ++n;
      return n;
    }
    for (std::size_t i = 0; i < slots_.size(); ++i)
      n += holds(s, i) ? 1 : 0;
    return n;
  }

  // Whether it reads the whole array at once (for the tests).
  bool reads_at_once() const { return run_.has_value(); }

private:
  // One bit (the lowest of its field) per id that holds one of the values.
  std::uint64_t matches(const State& s) const {
    const std::uint64_t code = s.code(run_->bits);
    std::uint64_t m = 0;
    for (const std::uint64_t pattern : patterns_)
      m |= run_->holding(code, pattern);
    return m;
  }
  bool holds(const State& s, std::size_t i) const {
    const T value = s.get<T>(slots_[i]);
    for (const T v : values_)
      if (value == v)
        return true;
    return false;
  }

  std::vector<T> values_;
  std::size_t first_;
  std::vector<Slot> slots_;
  std::optional<FieldRun> run_;
  std::vector<std::uint64_t> patterns_; // one per value, in every field of the run
};

} // namespace tioa
