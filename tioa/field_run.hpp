#pragma once
// Fields of one width that lie side by side in at most 63 bits of a state, as the
// variables of an array of small variables declared together do. One read gives all of
// them, and a few bit operations tell which fields hold a given code: the `.where` filter
// of a transition (transition.hpp, Binding) and the array queries (ids_where.hpp) read an
// array this way instead of one variable at a time.

#include <cstdint>
#include <optional>
#include <vector>

#include "tioa/variables.hpp"

namespace tioa {

// `code` holds the fields side by side, `width` bits each, `pattern` the admitted code in
// every field and `low` bit 0 of every field. The result has the lowest bit of each field
// that holds the admitted code.
inline std::uint64_t admitted_fields(std::uint64_t code, std::uint64_t pattern, std::uint64_t low,
                                     std::uint32_t width) {
  const std::uint64_t x = code ^ pattern;
  std::uint64_t nonzero = x; // a field of x is zero where the code is the admitted one
  for (std::uint32_t k = 1; k < width; ++k)
    nonzero |= x >> k;
  return ~nonzero & low;
}

struct FieldRun {
  Slot bits;                    // the whole run
  std::uint32_t width = 0;      // of one field
  std::uint64_t low = 0;        // bit 0 of every field
  std::uint32_t reciprocal = 0; // ⌈2^16 / width⌉, for field_of

  // `code` in every field.
  std::uint64_t pattern(std::uint64_t code) const { return code * low; }
  // The field that bit `bit` (< 64) of the run belongs to, without a division: the
  // rounding error of the reciprocal is below 64 / 2^16 < 1 / width, too small to cross
  // a multiple of 1 / width.
  std::uint32_t field_of(std::uint32_t bit) const { return (bit * reciprocal) >> 16; }
  // One bit (the lowest of its field) per field holding `pattern`'s code.
  std::uint64_t holding(std::uint64_t run_code, std::uint64_t pattern) const {
    return admitted_fields(run_code, pattern, low, width);
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
