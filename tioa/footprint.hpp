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
// A transition that declares none may read and write every variable of the automaton that
// declares it (sound, and precise enough for a component that serves one robot or one
// region). Composition unites the footprints of the components that take part in a step.
// A checker that relies on footprints checks them on every step it runs: a write outside
// the declared writes, or a read outside the declared reads, is a ModelError.

#include <algorithm>
#include <cstdint>
#include <functional>
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

// The two masks a footprint is written into, seen from a component placed `base` bits
// into the state.
class Footprint {
public:
  Footprint(Word* reads, Word* writes, std::uint32_t base)
      : reads_(reads), writes_(writes), base_(base) {}

  template <class T> Footprint& reads(const Variable<T>& v) {
    set_bits(reads_, base_ + v.slot.offset, v.slot.width);
    return *this;
  }
  template <class T> Footprint& writes(const Variable<T>& v) {
    set_bits(writes_, base_ + v.slot.offset, v.slot.width);
    return *this;
  }
  // Every bit of a component of `bits` bits, read and written (the default footprint).
  void whole(std::uint32_t bits) {
    set_bits(reads_, base_, bits);
    set_bits(writes_, base_, bits);
  }
  Footprint at(std::uint32_t offset) const { return Footprint(reads_, writes_, base_ + offset); }

private:
  Word* reads_;
  Word* writes_;
  std::uint32_t base_;
};

using FootprintFunction = std::function<void(const Params&, Footprint&)>;

// The reads and writes of every step of one action, over its whole parameter box.
struct ActionFootprint {
  std::vector<Word> reads, writes;
};

} // namespace tioa
