// ResetMC (seed 000 Definition 7.2) on hand-made states of VLayer[MC], clause by clause,
// and the reset states among the reachable states of the smallest instance.
#include <algorithm>
#include <random>

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

Clauses broken_reset_clauses(const vlayer_mc::VlConfig& c, const tioa::Automaton& layer,
                             const Words& s) {
  Words padded = s;
  padded.push_back(0);
  return vlayer_mc::reset_mc_clauses(c, layer)(tioa::State(padded.data(), 0));
}

} // namespace

TEST_CASE("vlayer ResetMC: each clause of Definition 7.2 on hand-made states", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const vlayer_mc::Lattice l = c.lattice();
  Words s(layer.words() + 1, 0);
  vlayer_mc::placed_start(layer, {l.point(1, 1)}).enumerate(s.data(), 0, [] {});
  s.resize(layer.words());
  CHECK(broken_reset_clauses(c, layer, s)
            .empty()); // the start: phase 0, no update yet, nothing queued

  Words t = s; // (2): a robot that knows where it is needs a target and velocity 0
  set(layer, t, "CN_0.cn.x", l.point(1, 1));
  set(layer, t, "CN_0.cn.clock", 0);
  set(layer, t, "VBcast.reg[0]", 0);
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(2) CN_0"});
  // At phase 0 clause (4b) of L1MC leaves no time to move: the target is where it stands.
  set(layer, t, "CN_0.cn.target", l.point(1, 1));
  set(layer, t, "CN_0.cn.v", vlayer_mc::zero_velocity);
  set(layer, t, "RW.vel[0]", vlayer_mc::zero_velocity);
  CHECK(broken_reset_clauses(c, layer, t).empty());
  set(layer, t, "CN_0.delay.held", 1); // to_send_p ≠ λ
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(2) CN_0"});

  t = s;
  set(layer, t, "VN_1.out[0]", l.point(3, 1)); // (3): to_send_u ≠ λ
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(3) VN_1"});
  t = s;
  set(layer, t, "VBcast.vn_mask[0]", 1); // (4): a message still processing
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(4)"});
  t = s;
  set(layer, t, "RW.gps_age[0]", 0); // (5): a GPSupdate already at this time
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(5)"});
  set(layer, t, "RW.now", 1);
  set(layer, t, "RW.gps_age[0]", 1);
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(5)"});
  t = s;
  set(layer, t, "VN_0.clock", 3); // (1): via L1MC (2)
  CHECK(broken_reset_clauses(c, layer, t) == Clauses{"(1) (2) VN_0"});
}

// The reset states among the reachable states of the smallest instance: the start, and
// those a round start reaches again (ResetMC is met after every round, Lemma 7.4's target).
TEST_CASE("vlayer ResetMC: reset states recur in the smallest instance", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const tioa::SuccessorGenerator generator(layer);
  const auto ex =
      checker::explore(generator, vlayer_mc::placed_start(layer, {c.lattice().point(0, 2)}), {});
  REQUIRE(ex.complete());
  const auto reset = vlayer_mc::reset_mc(c, layer, vlayer_mc::MWindow::closed);
  std::size_t resets = 0;
  for (checker::StateId id = 0; id < ex.store.size(); ++id)
    resets += reset(tioa::State(ex.store.state(id), 0)) ? 1 : 0;
  CHECK(resets == 32);
}

// D30: a robot that stands without a target while its cn-update is due is not in ResetMC
// ((2) wants x*_p ≠ ⊥), but it differs from the ResetMC state z with x*_p := x_p only in
// what the cn-update overwrites: every step from it is a step from z to the same state up to
// x*_p, and after the vcast the two are the same state.
TEST_CASE("vlayer ResetMC: a robot without a target whose cn-update is due (D30)", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const vlayer_mc::Lattice l = c.lattice();
  const auto closed = vlayer_mc::MWindow::closed;
  const auto reset = vlayer_mc::reset_mc(c, layer, closed);
  const auto relaxed = vlayer_mc::reset_mc_or_targetless(c, layer, closed);
  const auto holds = [&](const tioa::StatePredicate& p, Words s) {
    s.push_back(0);
    return p(tioa::State(s.data(), 0));
  };
  Words s(layer.words() + 1, 0);
  vlayer_mc::placed_start(layer, {l.point(3, 1)}).enumerate(s.data(), 0, [] {});
  s.resize(layer.words());
  set(layer, s, "CN_0.cn.x", l.point(3, 1));
  set(layer, s, "CN_0.cn.clock", 0);
  set(layer, s, "CN_0.cn.v", vlayer_mc::zero_velocity);
  set(layer, s, "RW.vel[0]", vlayer_mc::zero_velocity);
  set(layer, s, "VBcast.reg[0]", 1);
  REQUIRE(get(layer, s, "CN_0.cn.since") == 1); // the cn-update is due
  CHECK_FALSE(holds(reset, s));
  CHECK(holds(relaxed, s));

  Words z = s;
  set(layer, z, "CN_0.cn.target", l.point(3, 1));
  CHECK(holds(reset, z));
  const auto from_s = steps(layer, s), from_z = steps(layer, z);
  REQUIRE(from_s.size() == from_z.size());
  for (std::size_t i = 0; i < from_s.size(); ++i) {
    REQUIRE(from_s[i].label == from_z[i].label);
    Words up_to_target = from_z[i].state;
    set(layer, up_to_target, "CN_0.cn.target",
        get(layer, from_s[i].state, "CN_0.cn.target").value_or(vl_test::bottom));
    CHECK(up_to_target == from_s[i].state);
  }
  const std::string vcast = "vcast_cn_update_0(" + std::to_string(l.point(3, 1)) + ")";
  CHECK(after(layer, s, vcast) == after(layer, z, vcast));

  Words sent = s; // once the cn-update is sent, no: nothing overwrites x*_p any more
  set(layer, sent, "CN_0.cn.since", 0);
  CHECK_FALSE(holds(relaxed, sent));
  Words moving = s; // nor with a velocity other than 0
  set(layer, moving, "CN_0.cn.v", vl_test::bottom);
  CHECK_FALSE(holds(relaxed, moving));
}

// Finding F6: a robot whose region's VSA has failed gets no target, so at every later round
// start x*_p = ⊥ and the execution never meets ResetMC again, although it stays in LMC (it
// started in ResetMC). Lemma 7.4's proof ("we eventually arrive at a state in ResetMC") does
// not cover it; D30's states do, at every round start.
TEST_CASE("vlayer ResetMC: finding F6, never ResetMC again under a failed VSA", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const vlayer_mc::Lattice l = c.lattice();
  const auto closed = vlayer_mc::MWindow::closed;
  Words z(layer.words() + 1, 0);
  vlayer_mc::placed_start(layer, {l.point(3, 1)}).enumerate(z.data(), 0, [] {});
  z.resize(layer.words());
  for (const auto& [name, value] :
       std::vector<std::pair<std::string, std::int64_t>>{{"CN_0.cn.x", l.point(3, 1)},
                                                         {"CN_0.cn.target", l.point(3, 1)},
                                                         {"CN_0.cn.clock", 0},
                                                         {"CN_0.cn.v", vlayer_mc::zero_velocity},
                                                         {"RW.vel[0]", vlayer_mc::zero_velocity},
                                                         {"VBcast.reg[0]", 1},
                                                         {"VN_0.clock", 0},
                                                         {"VN_1.failed", 1}})
    set(layer, z, name, value);
  const auto system =
      tioa::Start(layer, tioa::StartSet::listed(layer.layout().bits(), layer.words(), z, "z"));
  const auto ex = checker::explore(tioa::SuccessorGenerator(system), system.start(), {});
  REQUIRE(ex.complete());
  const auto reset = vlayer_mc::reset_mc(c, layer, closed);
  const auto relaxed = vlayer_mc::reset_mc_or_targetless(c, layer, closed);
  std::size_t resets = 0, targetless = 0;
  for (checker::StateId id = 0; id < ex.store.size(); ++id) {
    const tioa::State state(ex.store.state(id), 0);
    if (reset(state)) { // only at instant 0: z, before and after VW's time updates
      ++resets;
      Words w(ex.store.state(id), ex.store.state(id) + layer.words());
      for (const auto& v : layer.layout().variables())
        if (v.name.rfind("VW.age", 0) != 0)
          CHECK(get(layer, w, v.name) == get(layer, z, v.name));
    }
    targetless += relaxed(state) && !reset(state) ? 1 : 0;
  }
  CHECK(resets == 4);     // VW.age[0], VW.age[1] each 0 or 1
  CHECK(targetless == 4); // at the later round starts, before and after the time updates
}

// The symbolic checks build ResetMC-or-targetless from its conjuncts: on 5,000 of the first
// 200,000 states reachable from the placed start of the default instance, and on each of them with
// one variable at a random code, their conjunction is reset_mc_or_targetless.
TEST_CASE("vlayer ResetMC: the conjuncts together are reset_mc_or_targetless", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto layer = vlayer_mc::vlayer(c, {.robots = true, .vsas = true});
  const vlayer_mc::Lattice l = c.lattice();
  const tioa::Automaton placed =
      tioa::Start(layer, vlayer_mc::placed_start(layer, {l.point(1, 1)}));
  const tioa::SuccessorGenerator generator(placed);
  checker::ExploreOptions first;
  first.limits.max_states = 200'000; // (the first levels are enough)
  const checker::Exploration ex = checker::explore(generator, placed.start(), first);
  std::mt19937_64 random(11);
  const auto& variables = layer.layout().variables();
  for (const auto window : {vlayer_mc::MWindow::as_printed, vlayer_mc::MWindow::closed}) {
    const auto whole = vlayer_mc::reset_mc_or_targetless(c, layer, window);
    const auto conjuncts = vlayer_mc::reset_mc_or_targetless_conjuncts(c, layer, window);
    int inside = 0, outside = 0;
    checker::StateReader read(ex);
    const std::uint64_t stride = std::max<std::uint64_t>(1, ex.store.size() / 5000);
    for (checker::StateId id = 0; id < ex.store.size(); id += stride) {
      for (int mutated = 0; mutated < 2; ++mutated) {
        Words s(read(id), read(id) + layer.words());
        s.push_back(0);
        tioa::State state(s.data(), 0);
        if (mutated) {
          const auto& v = variables[random() % variables.size()];
          state.set_code(v.slot(), std::uniform_int_distribution<std::uint64_t>(0, v.code_count() -
                                                                                       1)(random));
        }
        const bool all = std::all_of(conjuncts.begin(), conjuncts.end(),
                                     [&](const tioa::StatePredicate& p) { return p(state); });
        const bool in = whole(state);
        CHECK(in == all);
        (in ? inside : outside) += 1;
      }
    }
    CHECK(inside > 0);
    CHECK(outside > 0);
  }
}
