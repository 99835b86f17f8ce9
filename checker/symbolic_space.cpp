#include "checker/symbolic_space.hpp"

#include <stdexcept>

namespace checker::symbolic {

namespace {

bool session_open = false;

} // namespace

BddSession::BddSession(std::uint32_t bits) {
  if (session_open)
    throw std::logic_error("one BddSession at a time");
  session_open = true;
  bdd_init(1'000'000, 400'000);
  bdd_setmaxincrease(4'000'000);
  bdd_setcacheratio(4);
  bdd_gbc_hook(nullptr);
  bdd_setvarnum(static_cast<int>(2 * std::max<std::uint32_t>(bits, 1)));
}

BddSession::~BddSession() {
  bdd_done();
  session_open = false;
}

void BddSession::reorder_by_variables(const tioa::StateLayout& layout) {
  for (const auto& v : layout.variables())
    if (v.width > 0)
      bdd_intaddvarblock(static_cast<int>(2 * v.offset),
                         static_cast<int>(2 * (v.offset + v.width) - 1), BDD_REORDER_FIXED);
  bdd_reorder_verbose(0);
  bdd_autoreorder(BDD_REORDER_SIFT);
}

Space::Space(const tioa::Automaton& automaton)
    : automaton_(&automaton), bits_(automaton.layout().bits()), words_(automaton.words()) {
  variable_of_bit_.assign(bits_, -1);
  for (const auto& v : automaton.layout().variables()) {
    if (v.width == 0)
      continue;
    for (std::uint32_t b = v.offset; b < v.offset + v.width; ++b)
      variable_of_bit_[b] = static_cast<int>(variables_.size());
    variables_.push_back({v.name, v.offset, v.width, v.code_count()});
  }
  std::vector<Word> state(words_, 0);
  for (const Variable& v : variables_) {
    bdd codes = bddfalse;
    for (std::uint64_t c = 0; c < v.codes; ++c) {
      set_code(state.data(), v, c);
      bdd one = bddtrue;
      for (std::uint32_t b = v.offset; b < v.offset + v.width; ++b)
        one &= bit(state.data(), b) ? current(b) : !current(b);
      codes |= one;
    }
    valid_ &= codes;
  }
  for (std::uint32_t b = 0; b < bits_; ++b)
    current_bits_ &= current(b);
}

void Space::set_bit(Word* state, std::uint32_t b, bool value) {
  if (value)
    state[b >> 6] |= Word{1} << (b & 63);
  else
    state[b >> 6] &= ~(Word{1} << (b & 63));
}

void Space::set_code(Word* state, const Variable& v, std::uint64_t code) const {
  for (std::uint32_t i = 0; i < v.width; ++i)
    set_bit(state, v.offset + i, (code >> i) & 1);
}

bdd Space::cube(const Word* state, const std::vector<char>& assigned) const {
  bdd c = bddtrue;
  for (std::size_t i = variables_.size(); i-- > 0;) {
    if (!assigned[i])
      continue;
    const Variable& v = variables_[i];
    for (std::uint32_t b = v.offset + v.width; b-- > v.offset;)
      c &= bit(state, b) ? current(b) : !current(b);
  }
  return c;
}

bdd Space::state_set(const Word* state) const {
  return cube(state, std::vector<char>(variables_.size(), 1));
}

std::vector<Word> Space::pick(const bdd& set) const {
  const bdd one = bdd_satoneset(set, current_bits_, bddfalse);
  std::vector<Word> state(words_, 0);
  for (std::uint32_t b = 0; b < bits_; ++b)
    set_bit(state.data(), b, (one & current(b)) != bddfalse);
  return state;
}

bdd move_set(const bdd& set, const Space& from, const Space& to) {
  // Through the next bits, so that a bit that moves never lands on one still to move.
  bddPair* to_next = bdd_newpair();
  bddPair* to_place = bdd_newpair();
  for (const auto& v : from.variables()) {
    const tioa::VariableInfo* target = to.automaton().layout().find(v.name);
    if (!target || target->width != v.width)
      throw std::invalid_argument("move_set: " + v.name + " is not a variable of the target");
    for (std::uint32_t b = 0; b < v.width; ++b) {
      bdd_setpair(to_next, static_cast<int>(2 * (v.offset + b)),
                  static_cast<int>(2 * (v.offset + b) + 1));
      bdd_setpair(to_place, static_cast<int>(2 * (v.offset + b) + 1),
                  static_cast<int>(2 * (target->offset + b)));
    }
  }
  const bdd moved = bdd_replace(bdd_replace(set, to_next), to_place);
  bdd_freepair(to_next);
  bdd_freepair(to_place);
  return moved;
}

} // namespace checker::symbolic
