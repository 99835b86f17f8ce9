// The known part of LMC as a set of states for the symbolic checks
// (proofs/vlayer_mc/symbolic_lmc.hpp) against KnownLmc::contains: every state of a plain
// exploration of the reset family is in it (most of them are not their class's
// representative), and each of those states with one variable at a random code is in it
// exactly when KnownLmc::contains says so.
#include <catch2/catch.hpp>

#include <random>

#include "checker/explorer.hpp"
#include "checker/symbolic_space.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "proofs/vlayer_mc/symbolic_lmc.hpp"
#include "tioa/operators.hpp"

namespace sym = checker::symbolic;

TEST_CASE("vlayer-mc known LMC: the symbolic set is the states KnownLmc contains",
          "[vlayer][lmc][symbolic]") {
  vlayer_mc::VlConfig c;
  c.cols = 1;
  const tioa::Automaton layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const vlayer_mc::KnownLmc known(c, layer, {});
  REQUIRE(known.complete());
  const tioa::Automaton family = known.from_family(layer);
  const checker::Exploration ex =
      checker::explore(tioa::SuccessorGenerator(family), family.start(), {});
  REQUIRE(ex.complete());
  REQUIRE(ex.store.size() > known.size()); // most states are not representatives

  const sym::BddSession session(layer.layout().bits());
  const sym::Space space(layer);
  sym::LearningFigures figures;
  const bdd set = vlayer_mc::known_lmc_set(space, known, figures);
  const auto in_set = [&](const tioa::Word* s) { return (set & space.state_set(s)) != bddfalse; };

  std::mt19937_64 random(3);
  const auto& variables = layer.layout().variables();
  int inside = 0, outside = 0;
  checker::StateReader read(ex);
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    std::vector<tioa::Word> s(read(id), read(id) + layer.words());
    s.push_back(0);
    CHECK(in_set(s.data()));
    tioa::State state(s.data(), 0);
    const auto& v = variables[random() % variables.size()];
    state.set_code(v.slot(),
                   std::uniform_int_distribution<std::uint64_t>(0, v.code_count() - 1)(random));
    const bool in = known.contains(state);
    CHECK(in_set(s.data()) == in);
    (in ? inside : outside) += 1;
  }
  CHECK(inside > 0);
  CHECK(outside > 0);
}
