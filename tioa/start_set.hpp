#pragma once
// Sets of start states (Def 3.1 (c)), enumerated lazily: U(A) of a model with 10^7
// valuations never materialises them. An enumerator writes one start state after the
// other into a state buffer (at the bit `base` where its automaton lives) and calls
// `visit` for each.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tioa/state.hpp"
#include "tioa/variables.hpp"

namespace tioa {

using StatePredicate = std::function<bool(const State&)>;

class StartSet {
public:
  using Visit = std::function<void()>;
  using Enumerate = std::function<void(Word* words, std::uint32_t base, const Visit& visit)>;

  StartSet() = default;
  StartSet(std::string description, Enumerate enumerate)
      : description_(std::move(description)), enumerate_(std::move(enumerate)) {}

  void enumerate(Word* words, std::uint32_t base, const Visit& visit) const {
    if (enumerate_)
      enumerate_(words, base, visit);
  }
  const std::string& description() const { return description_; }

  // Each variable at its declared initial value, or ranging over its domain if it has none.
  static StartSet declared(const StateLayout& layout);
  // Every valuation of the layout's finite domains: the start set of U(A).
  static StartSet every_valuation(const StateLayout& layout);
  // Every valuation that satisfies `legal`: the start set of Start(A, L).
  static StartSet satisfying(const StateLayout& layout, StatePredicate legal,
                             std::string description);
  // A fixed list of states, each `bits` long at bit 0 of its own `words`-word buffer.
  static StartSet listed(std::uint32_t bits, std::uint32_t words, std::vector<Word> states,
                         std::string description);

private:
  std::string description_;
  Enumerate enumerate_;
};

// Copies `bits` bits from src (from bit src_base) to dst (from bit dst_base).
void copy_bits(Word* dst, std::uint32_t dst_base, const Word* src, std::uint32_t src_base,
               std::uint32_t bits);

} // namespace tioa
