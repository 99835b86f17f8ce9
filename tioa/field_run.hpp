#pragma once
// Fields of one width that lie side by side in at most 63 bits of a state, as the
// variables of an array of small variables declared together do. One read gives all of
// them, and a few bit operations tell which fields hold a given code: the `.where` filter
// of a transition (transition.hpp, Binding) and the array queries (ids_where.hpp) read an
// array this way instead of one variable at a time.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "tioa/variables.hpp"

namespace tioa {

struct FieldRun {
  Slot bits;                    // the whole run
  std::uint32_t width = 0;      // of one field
  std::uint64_t low = 0;        // bit 0 of every field
  std::uint32_t reciprocal = 0; // ⌈2^16 / width⌉, for field_of
  // differing()'s shifts: each ORs bits [k, k + covered) of a field into bit k, until
  // `covered` reaches the width (at most 6 shifts for 63 bits).
  std::uint8_t fold_shifts[6] = {};
  std::uint32_t folds = 0;

  // Bit 0 of each field of `x` is set when the field is not zero (the other bits: noise).
  std::uint64_t differing(std::uint64_t x) const {
    for (std::uint32_t k = 0; k < folds; ++k)
      x |= x >> fold_shifts[k];
    return x;
  }

  // `code` in every field.
  std::uint64_t pattern(std::uint64_t code) const { return code * low; }
  // The field that bit `bit` (< 64) of the run belongs to, without a division: the
  // rounding error of the reciprocal is below 64 / 2^16 < 1 / width, too small to cross
  // a multiple of 1 / width.
  std::uint32_t field_of(std::uint32_t bit) const { return (bit * reciprocal) >> 16; }
  // One bit (the lowest of its field) per field holding `pattern`'s code.
  std::uint64_t holding(std::uint64_t run_code, std::uint64_t pattern) const {
    return ~differing(run_code ^ pattern) & low;
  }
};

// The fields `count` fields of `width` bits from bit `offset` make (count * width < 64).
inline FieldRun field_run_at(std::uint32_t offset, std::uint32_t width, std::uint32_t count) {
  FieldRun run;
  run.bits = Slot::bits(offset, static_cast<std::uint8_t>(count * width));
  run.width = width;
  for (std::uint32_t i = 0; i < count; ++i)
    run.low |= std::uint64_t{1} << (i * width);
  run.reciprocal = ((std::uint32_t{1} << 16) + width - 1) / width;
  for (std::uint32_t covered = 1; covered < width;) {
    const std::uint32_t shift = std::min(covered, width - covered);
    run.fold_shifts[run.folds++] = static_cast<std::uint8_t>(shift);
    covered += shift;
  }
  return run;
}

// The run `slots` make, if they lie one after the other, all as wide, in at most 63 bits.
inline std::optional<FieldRun> field_run(const std::vector<Slot>& slots) {
  if (slots.empty())
    return std::nullopt;
  const std::uint32_t width = slots.front().width;
  if (width == 0 || slots.size() * width > 63)
    return std::nullopt;
  for (std::size_t i = 1; i < slots.size(); ++i)
    if (slots[i].width != width || slots[i].offset != slots.front().offset + i * width)
      return std::nullopt;
  return field_run_at(slots.front().offset, width, static_cast<std::uint32_t>(slots.size()));
}

} // namespace tioa
