// ResetMC (seed 000 Definition 7.2) on hand-made states of VLayer[MC], clause by clause,
// and the reset states among the reachable states of the smallest instance.
#include <catch2/catch.hpp>

#include "checker/checks.hpp"
#include "checker/explorer.hpp"
#include "models/vlayer_mc/reset_mc.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"
#include "tioa/operators.hpp"

using namespace vl_test;

namespace {

using Clauses = std::vector<std::string>;

Clauses broken(const vlayer::VlConfig& c, const tioa::Automaton& layer, const Words& s) {
  Words padded = s;
  padded.push_back(0);
  return vlayer::reset_mc_clauses(c, layer)(tioa::State(padded.data(), 0));
}

} // namespace

TEST_CASE("vlayer ResetMC: each clause of Definition 7.2 on hand-made states", "[vlayer]") {
  const vlayer::VlConfig c;
  const auto layer = vlayer::vlayer(c, {.robots = false, .vsas = false});
  const vlayer::Lattice l = c.lattice();
  Words s(layer.words() + 1, 0);
  vlayer::placed_start(layer, {l.point(1, 1)}).enumerate(s.data(), 0, [] {});
  s.resize(layer.words());
  CHECK(broken(c, layer, s).empty()); // the start: phase 0, no update yet, nothing queued

  Words t = s; // (2): a robot that knows where it is needs a target and velocity 0
  set(layer, t, "CN_0.cn.x", l.point(1, 1));
  set(layer, t, "CN_0.cn.clock", 0);
  set(layer, t, "VBcast.reg[0]", 0);
  CHECK(broken(c, layer, t) == Clauses{"(2) CN_0"});
  // At phase 0 clause (4b) of L1MC leaves no time to move: the target is where it stands.
  set(layer, t, "CN_0.cn.target", l.point(1, 1));
  set(layer, t, "CN_0.cn.v", vlayer::zero_velocity);
  set(layer, t, "RW.vel[0]", vlayer::zero_velocity);
  CHECK(broken(c, layer, t).empty());
  set(layer, t, "CN_0.delay.held", 1); // to_send_p ≠ λ
  CHECK(broken(c, layer, t) == Clauses{"(2) CN_0"});

  t = s;
  set(layer, t, "VN_1.out[0]", l.point(3, 1)); // (3): to_send_u ≠ λ
  CHECK(broken(c, layer, t) == Clauses{"(3) VN_1"});
  t = s;
  set(layer, t, "VBcast.vn_mask[0]", 1); // (4): a message still processing
  CHECK(broken(c, layer, t) == Clauses{"(4)"});
  t = s;
  set(layer, t, "RW.gps_age[0]", 0); // (5): a GPSupdate already at this time
  CHECK(broken(c, layer, t) == Clauses{"(5)"});
  set(layer, t, "RW.now", 1);
  set(layer, t, "RW.gps_age[0]", 1);
  CHECK(broken(c, layer, t) == Clauses{"(5)"});
  t = s;
  set(layer, t, "VN_0.clock", 3); // (1): via L1MC (2)
  CHECK(broken(c, layer, t) == Clauses{"(1) (2) VN_0"});
}

// The reset states among the reachable states of the smallest instance: the start, and
// those a round start reaches again (ResetMC is met after every round, Lemma 7.4's target).
TEST_CASE("vlayer ResetMC: reset states recur in the smallest instance", "[vlayer]") {
  const vlayer::VlConfig c;
  const auto layer = vlayer::vlayer(c, {.robots = false, .vsas = false});
  const tioa::SuccessorGenerator generator(layer);
  const auto ex =
      checker::explore(generator, vlayer::placed_start(layer, {c.lattice().point(0, 2)}), {});
  REQUIRE(ex.complete());
  const auto reset = vlayer::reset_mc(c, layer, vlayer::MWindow::closed);
  std::size_t resets = 0;
  for (checker::StateId id = 0; id < ex.store.size(); ++id)
    resets += reset(tioa::State(ex.store.state(id), 0)) ? 1 : 0;
  CHECK(resets == 32);
}
