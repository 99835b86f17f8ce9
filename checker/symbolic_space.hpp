#pragma once
// Sets of states as binary decision diagrams (BuDDy, Debian's libbdd-dev): the symbolic side
// of the checker, after LTSmin's symbolic back end. Each bit b of a state is two BDD
// variables, the current value 2b and the next value 2b + 1 (interleaved, so that a step's
// relation stays small); the bits of one state variable move together when BuDDy reorders
// (sifting, on), which is what keeps the sets of VLayer[MC] in thousands of nodes rather than
// millions (in the layout's order they grow past 2 million nodes at the first instant).
//
// BuDDy has one global table: a BddSession opens it and closes it; there is at most one at a
// time, and every bdd must be gone before it closes. Single-threaded.

#include <bdd.h>

#include <cstdint>
#include <string>
#include <vector>

#include "tioa/automaton.hpp"

namespace checker::symbolic {

using tioa::Word;

class BddSession {
public:
  // Room for states of up to `bits` bits (every automaton of the run).
  explicit BddSession(std::uint32_t bits);
  ~BddSession();
  BddSession(const BddSession&) = delete;
  BddSession& operator=(const BddSession&) = delete;
  // Lets BuDDy reorder the variables, each state variable of `layout` kept as one block
  // (declare them once, for the automaton whose sets grow).
  static void reorder_by_variables(const tioa::StateLayout& layout);
};

// The variables of one automaton's state, and its sets over their current bits.
class Space {
public:
  struct Variable {
    std::string name;
    std::uint32_t offset, width;
    std::uint64_t codes;
  };

  explicit Space(const tioa::Automaton& automaton);

  const tioa::Automaton& automaton() const { return *automaton_; }
  std::uint32_t bits() const { return bits_; }
  std::uint32_t words() const { return words_; }
  const std::vector<Variable>& variables() const { return variables_; }
  // The variable a bit belongs to (-1: none, a bit past the last variable).
  int variable_of_bit(std::uint32_t bit) const { return variable_of_bit_[bit]; }

  static bdd current(std::uint32_t bit) { return bdd_ithvarpp(static_cast<int>(2 * bit)); }
  static bdd next(std::uint32_t bit) { return bdd_ithvarpp(static_cast<int>(2 * bit + 1)); }
  static bool bit(const Word* state, std::uint32_t b) { return (state[b >> 6] >> (b & 63)) & 1; }
  static void set_bit(Word* state, std::uint32_t b, bool value);
  void set_code(Word* state, const Variable& v, std::uint64_t code) const;

  // The state's values of the variables `assigned` marks, as a cube over current bits.
  bdd cube(const Word* state, const std::vector<char>& assigned) const;
  // The whole state as a cube.
  bdd state_set(const Word* state) const;
  // Every state whose every variable holds one of its codes.
  const bdd& valid() const { return valid_; }
  // The current bits of every variable (for counting and picking states).
  const bdd& current_bits() const { return current_bits_; }
  // How many states a set over current bits holds.
  double count(const bdd& set) const { return bdd_satcountset(set, current_bits_); }
  // One state of a non-empty set.
  std::vector<Word> pick(const bdd& set) const;

private:
  const tioa::Automaton* automaton_;
  std::uint32_t bits_, words_;
  std::vector<Variable> variables_;
  std::vector<int> variable_of_bit_;
  bdd valid_ = bddtrue, current_bits_ = bddtrue;
};

// A set of `from`'s states moved onto `to`'s bits, variable by variable of the same name
// (every variable of `from` must be one of `to`'s).
bdd move_set(const bdd& set, const Space& from, const Space& to);

} // namespace checker::symbolic
