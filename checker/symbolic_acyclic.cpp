#include "checker/symbolic_acyclic.hpp"

namespace checker::symbolic {

namespace {

// A variable's code before (current bits) and after a step of a group that writes `writes`
// (next bits where it writes, current bits where it keeps them).
struct Codes {
  std::vector<bdd> before, after; // least significant bit first
};

Codes codes_of(const Space::Variable& v, const std::vector<Word>& writes) {
  Codes c;
  for (std::uint32_t b = v.offset; b < v.offset + v.width; ++b) {
    c.before.push_back(Space::current(b));
    c.after.push_back(Space::bit(writes.data(), b) ? Space::next(b) : Space::current(b));
  }
  return c;
}

// after < before, as unsigned numbers (most significant bit first).
bdd lower(const std::vector<bdd>& after, const std::vector<bdd>& before) {
  bdd less = bddfalse, equal_above = bddtrue;
  for (std::size_t i = after.size(); i-- > 0;) {
    less |= equal_above & !after[i] & before[i];
    equal_above &= bdd_biimp(after[i], before[i]);
  }
  return less;
}

bdd same(const Codes& c) {
  bdd equal = bddtrue;
  for (std::size_t i = 0; i < c.before.size(); ++i)
    equal &= bdd_biimp(c.after[i], c.before[i]);
  return equal;
}

bool writes_any(const Space::Variable& v, const std::vector<Word>& writes) {
  for (std::uint32_t b = v.offset; b < v.offset + v.width; ++b)
    if (Space::bit(writes.data(), b))
      return true;
  return false;
}

} // namespace

bool no_cycle_proved(const Space& space, const std::vector<StepRelation>& groups) {
  std::vector<bdd> left;
  for (const StepRelation& g : groups)
    left.push_back(g.relation() & space.valid());
  const auto all_gone = [&] {
    for (const bdd& r : left)
      if (r != bddfalse)
        return false;
    return true;
  };
  for (bool cut = true; cut && !all_gone();) {
    cut = false;
    // A group none of whose steps can be followed by a step of the groups left is on no
    // cycle of them.
    bdd some_step = bddfalse;
    for (std::size_t g = 0; g < groups.size(); ++g)
      some_step |= groups[g].sources(left[g]);
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (left[g] != bddfalse && (groups[g].targets(left[g]) & some_step) == bddfalse) {
        left[g] = bddfalse;
        cut = true;
      }
    for (const Space::Variable& v : space.variables()) {
      bool never_lowers = true, never_raises = true, written = false;
      for (std::size_t g = 0; g < groups.size() && (never_lowers || never_raises); ++g) {
        if (left[g] == bddfalse || !writes_any(v, groups[g].writes()))
          continue;
        written = true;
        const Codes c = codes_of(v, groups[g].writes());
        never_lowers = never_lowers && (left[g] & lower(c.after, c.before)) == bddfalse;
        never_raises = never_raises && (left[g] & lower(c.before, c.after)) == bddfalse;
      }
      if (!written || (!never_lowers && !never_raises))
        continue;
      for (std::size_t g = 0; g < groups.size(); ++g) {
        if (left[g] == bddfalse || !writes_any(v, groups[g].writes()))
          continue;
        const bdd kept = left[g] & same(codes_of(v, groups[g].writes()));
        if (kept != left[g]) {
          left[g] = kept;
          cut = true;
        }
      }
    }
  }
  return all_gone();
}

} // namespace checker::symbolic
