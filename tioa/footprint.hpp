#pragma once
// What a step may read and what it may write, as bit masks over the state: the
// dependency information that partial-order reduction needs to decide that two steps are
// independent (LTSmin's dependency matrix, per step).
//
// A transition declares its footprint as a function of its parameters:
//
//   vw.output("time_" + u, {{"t", 0, delta - 1}})
//       .pre(...).eff(...)
//       .footprint([=](const Params&, Footprint& f) { f.reads(now).reads(age[u]).writes(age[u]);
//       });
//
// A write may declare its value: `f.sets(clock, m[1])` says the step leaves `clock` as it
// was or sets it to m[1] (never to anything else); `f.sets_bottom(target)` the same with
// ⊥. The zero-time reduction uses these values to see that a step cannot enable another
// within one instant (a guard waiting for clock == 2 stays false when every step that
// may write `clock` in this instant sets it to the current time, 0).
//
// A transition that declares none may read and write every variable of the automaton that
// declares it (sound, and precise enough for a component that serves one robot or one
// region). Composition unites the footprints of the components that take part in a step.
// A checker that relies on footprints checks them on every step it runs: a write outside
// the declared writes, or a read outside the declared reads, is a ModelError.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

#include "tioa/actions.hpp"
#include "tioa/variables.hpp"

namespace tioa {

// Sets bits [offset, offset + width) of a mask of words.
inline void set_bits(Word* mask, std::uint32_t offset, std::uint32_t width) {
  for (std::uint32_t bit = offset; bit < offset + width;) {
    const std::uint32_t word = bit >> 6, shift = bit & 63;
    const std::uint32_t take = std::min<std::uint32_t>(64 - shift, offset + width - bit);
    const Word ones = take == 64 ? ~Word{0} : ((Word{1} << take) - 1);
    mask[word] |= ones << shift;
    bit += take;
  }
}

// A declared value: the step leaves bits [offset, offset + width) as they were or sets
// them to `code` (a packed code, as State stores it).
struct Assignment {
  std::uint32_t offset = 0;
  std::uint32_t width = 0;
  Word code = 0;
};

// What a footprint says about the values it writes, for a reader that asks: the declared
// values, and the bits written without one (`plain`, as many words as the state).
struct DeclaredValues {
  std::vector<Assignment> sets;
  Word* plain = nullptr;
};

// The two masks a footprint is written into, seen from a component placed `base` bits
// into the state; and, when asked for, the declared values.
class Footprint {
public:
  Footprint(Word* reads, Word* writes, std::uint32_t base, DeclaredValues* values = nullptr)
      : reads_(reads), writes_(writes), values_(values), base_(base) {}

  template <class T> Footprint& reads(const Variable<T>& v) {
    set_bits(reads_, base_ + v.slot.offset, v.slot.width);
    return *this;
  }
  template <class T> Footprint& writes(const Variable<T>& v) {
    set_bits(writes_, base_ + v.slot.offset, v.slot.width);
    if (values_)
      set_bits(values_->plain, base_ + v.slot.offset, v.slot.width);
    return *this;
  }
  // Writes `v`, leaving it as it was or setting it to `value`.
  template <class T> Footprint& sets(const Variable<T>& v, std::type_identity_t<T> value) {
    std::int64_t code = 0;
    if constexpr (std::is_same_v<T, bool>)
      code = value ? 1 : 0;
    else
      code = static_cast<std::int64_t>(value) - v.slot.lo;
    if (code < 0 || static_cast<std::uint64_t>(code) >= v.slot.value_codes)
      throw_declared_out_of_domain(v.slot, static_cast<std::int64_t>(value));
    return sets_code(v.slot, static_cast<Word>(code));
  }
  // Writes `v`, leaving it as it was or setting it to ⊥.
  template <class T> Footprint& sets_bottom(const Variable<T>& v) {
    if (!v.slot.has_bottom)
      throw_declared_out_of_domain(v.slot, static_cast<std::int64_t>(v.slot.value_codes));
    return sets_code(v.slot, v.slot.value_codes);
  }
  // Every bit of a component of `bits` bits, read and written (the default footprint).
  void whole(std::uint32_t bits) {
    set_bits(reads_, base_, bits);
    set_bits(writes_, base_, bits);
    if (values_)
      set_bits(values_->plain, base_, bits);
  }
  Footprint at(std::uint32_t offset) const {
    return Footprint(reads_, writes_, base_ + offset, values_);
  }

private:
  Footprint& sets_code(const Slot& slot, Word code) {
    set_bits(writes_, base_ + slot.offset, slot.width);
    if (values_)
      values_->sets.push_back({base_ + slot.offset, slot.width, code});
    return *this;
  }
  [[noreturn]] static void throw_declared_out_of_domain(const Slot& slot, std::int64_t value);

  Word* reads_;
  Word* writes_;
  DeclaredValues* values_;
  std::uint32_t base_;
};

using FootprintFunction = std::function<void(const Params&, Footprint&)>;

// The reads and writes of every step of one action, over its whole parameter box.
struct ActionFootprint {
  std::vector<Word> reads, writes;
};

} // namespace tioa
