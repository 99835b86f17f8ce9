// The known part of LMC (proofs/vlayer_mc/known_lmc.hpp, D29) is explored one class at a
// time (ExploreHooks::canonical). Cross-check: a plain exploration of the same reset family,
// with every state mapped to its class afterwards, gives exactly the same classes; and L1MC,
// which lmc-closure judges on representatives, gives each state its class's verdict.
#include <catch2/catch.hpp>

#include <set>

#include "checker/explorer.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/state_list.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/vlayer_mc/known_lmc.hpp"
#include "tioa/operators.hpp"

namespace {

using tioa::Word;

// Every combination of failed nodes over the reset family, as KnownLmc builds it.
tioa::Automaton family_with_failures(const vlayer_mc::VlConfig& c, const tioa::Automaton& layer) {
  std::vector<tioa::Slot> failed;
  for (const auto& v : layer.layout().variables())
    if (v.name.size() > 7 && v.name.compare(v.name.size() - 7, 7, ".failed") == 0)
      failed.push_back(v.slot());
  vlayer_mc::StateList family{layer.words(), {}};
  std::vector<Word> buffer(layer.words() + 1, 0);
  vlayer_mc::reset_family(c, layer).enumerate(buffer.data(), 0, [&] {
    for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << failed.size()); ++mask) {
      tioa::State s(buffer.data(), 0);
      for (std::size_t n = 0; n < failed.size(); ++n)
        s.set_code(failed[n], (mask >> n) & 1);
      family.data.insert(family.data.end(), buffer.begin(), buffer.begin() + layer.words());
    }
  });
  return tioa::Start(layer, family.start(layer, "the reset family, every failure"));
}

void require_same_classes(const vlayer_mc::VlConfig& c) {
  const tioa::Automaton layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const vlayer_mc::KnownLmc known(c, layer, {});
  REQUIRE(known.complete());

  const tioa::Automaton plain = family_with_failures(c, layer);
  const checker::Exploration ex =
      checker::explore(tioa::SuccessorGenerator(plain), plain.start(), {});
  REQUIRE(ex.complete());
  const vlayer_mc::ClauseCheck printed =
      vlayer_mc::l1mc_clauses(c, layer, vlayer_mc::MWindow::as_printed);
  const vlayer_mc::ClauseCheck closed =
      vlayer_mc::l1mc_clauses(c, layer, vlayer_mc::MWindow::closed);
  std::set<std::vector<Word>> classes;
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    const tioa::State s(ex.store.state(id), 0);
    CHECK(known.contains(s));
    const std::vector<Word> r = known.representative(s);
    classes.insert(r);
    CHECK(printed(s) == printed(tioa::State(r.data(), 0)));
    CHECK(closed(s) == closed(tioa::State(r.data(), 0)));
  }
  CHECK(classes.size() == known.size());
  CHECK(ex.store.size() > known.size()); // the classes do merge states
}

} // namespace

TEST_CASE("vlayer-mc known LMC: the classes explored equal the classes of a plain exploration",
          "[vlayer][lmc]") {
  vlayer_mc::VlConfig c;
  SECTION("1x1, one robot") {
    c.cols = 1;
    require_same_classes(c);
  }
  SECTION("1x2, one robot") {
    require_same_classes(c);
  }
}
