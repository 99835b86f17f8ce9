#include "proofs/vlayer_mc/symbolic_lmc.hpp"

namespace vlayer_mc {

namespace sym = checker::symbolic;

namespace {

// The states `s` with forget(s) in `set`, where forget sets f.rest to its codes when f
// applies to s: where it does not apply, `set` itself; where it does, the states that are
// in `set` once the rest holds its codes, whatever the rest holds.
bdd before_forgetting(const sym::Space& space, const KnownLmc::Forgetting& f, const bdd& set,
                      sym::LearningFigures& figures) {
  const bdd applies = sym::learn_predicate(
      space, [&f](const tioa::State& s) { return f.applies(s); }, figures);
  bdd initial = bddtrue, rest_bits = bddtrue;
  for (const auto& [slot, code] : f.rest)
    for (std::uint32_t i = 0; i < slot.width; ++i) {
      const bdd bit = sym::Space::current(slot.offset + i);
      initial &= (code >> i) & 1 ? bit : !bit;
      rest_bits &= bit;
    }
  return (set & !applies) | (applies & bdd_exist(set & initial, rest_bits));
}

} // namespace

bdd known_lmc_set(const sym::Space& space, const KnownLmc& known, sym::LearningFigures& figures) {
  const checker::Exploration& classes = known.exploration();
  checker::StateReader read(classes);
  bdd set = bddfalse;
  for (checker::StateId id = 0; id < classes.store.size(); ++id)
    set |= space.state_set(read(id));
  const auto& parts = known.forgetting();
  for (auto part = parts.rbegin(); part != parts.rend(); ++part)
    set = before_forgetting(space, *part, set, figures);
  return set & space.valid();
}

} // namespace vlayer_mc
