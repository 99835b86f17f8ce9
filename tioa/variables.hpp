#pragma once
// State variables of a TIOA (seed 000 §3.1, Def 3.1 (a)): every variable has a finite
// domain so that U(A) can enumerate every valuation. Values are stored as small unsigned
// codes packed into 64-bit words; a Variable<T> handle says where and how.

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace tioa {

using Word = std::uint64_t;

// `set`: a subset of a small named universe, as a bit mask (bit k: enum_names[k]).
enum class VariableKind { boolean, integer, enumeration, clock, set };

// Where a variable lives inside the state of the automaton that declared it.
// `offset` is relative to the first bit of that automaton's part of a state.
struct Slot {
  std::uint32_t offset = 0;
  std::uint8_t width = 0;
  bool has_bottom = false; // code `value_codes` is ⊥
  std::uint64_t mask = 0;  // (1 << width) - 1
  std::int64_t lo = 0;
  std::uint64_t value_codes = 0; // number of codes for values (hi - lo + 1)
  const char* name = "";         // interned, for error messages

  // A bare run of `width` bits at `offset` (no domain), for copying raw bits.
  static Slot bits(std::uint32_t offset, std::uint8_t width) {
    Slot slot;
    slot.offset = offset;
    slot.width = width;
    slot.mask = width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
    slot.value_codes = slot.mask;
    return slot;
  }
};

// A typed handle on a state variable; T is bool, int, or an enum type.
template <class T> struct Variable { Slot slot; };

// The ids an array of variables is indexed by: 0..count-1 by default, or the ids the
// paper uses (ids(1, n) for processes 1..N), so that `loc[p]` reads as in the figure.
struct IdRange {
  std::size_t first = 0;
  std::size_t count = 0;
  IdRange(std::size_t count) : count(count) {} // NOLINT: 0..count-1, implicitly
  IdRange(std::size_t first, std::size_t count) : first(first), count(count) {}
};
inline IdRange ids(std::size_t first, std::size_t last) {
  return IdRange(first, last >= first ? last - first + 1 : 0);
}

template <class T> struct VariableArray {
  std::vector<Variable<T>> items;
  std::size_t first = 0; // the id of items[0]

  // Unchecked, as in the hot loop; at() checks.
  const Variable<T>& operator[](std::size_t id) const { return items[id - first]; }
  const Variable<T>& at(std::size_t id) const { return items.at(id - first); }
  std::size_t size() const { return items.size(); }
  auto begin() const { return items.begin(); }
  auto end() const { return items.end(); }
};

struct VariableInfo {
  std::string name;
  VariableKind kind = VariableKind::integer;
  std::int64_t lo = 0;
  std::int64_t hi = 0;
  bool has_bottom = false;
  std::vector<std::string> enum_names;
  // The value at start (a code); nullopt means "any value of the domain".
  std::optional<std::uint64_t> initial_code;
  std::uint32_t offset = 0;
  std::uint8_t width = 0;

  std::uint64_t value_codes() const { return static_cast<std::uint64_t>(hi - lo + 1); }
  std::uint64_t code_count() const { return value_codes() + (has_bottom ? 1 : 0); }
  Slot slot() const;
  std::string render_code(std::uint64_t code) const;
};

// The variables of one automaton in declaration order, packed bit after bit.
class StateLayout {
public:
  const VariableInfo& add(VariableInfo info);
  const std::vector<VariableInfo>& variables() const { return variables_; }
  std::uint32_t bits() const { return bits_; }
  std::uint32_t words() const { return bits_ == 0 ? 1 : (bits_ + 63) / 64; }
  const VariableInfo* find(const std::string& name) const;
  // Appends `other` at bit `bits()`, prefixing every name; returns the base offset used.
  std::uint32_t append(const StateLayout& other, const std::string& prefix);

private:
  std::vector<VariableInfo> variables_;
  std::uint32_t bits_ = 0;
};

// Names live for the whole program so that slots can point at them cheaply.
const char* intern(const std::string& name);

} // namespace tioa
