// L1MC (seed 000 Definition 7.1) on hand-made states of VLayer[MC], clause by clause, and
// on every reachable state of the smallest instance.
#include <catch2/catch.hpp>

#include <random>

#include "checker/checks.hpp"
#include "checker/trace.hpp"
#include "models/vlayer_mc/l1mc.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"
#include "tioa/operators.hpp"

using namespace vl_test;

namespace {

std::vector<std::string> broken(const vlayer_mc::VlConfig& c, const tioa::Automaton& layer,
                                const Words& s) {
  Words padded = s;
  padded.push_back(0);
  return vlayer_mc::l1mc_clauses(c, layer)(tioa::State(padded.data(), 0));
}

using Clauses = std::vector<std::string>;

} // namespace

TEST_CASE("vlayer L1MC: each clause of Definition 7.1 on hand-made states", "[vlayer]") {
  const vlayer_mc::VlConfig c; // δ 6, e 0, d 1, ε 0 (target phase 2), d_r 1, ε_sample 1, vmax 4
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const vlayer_mc::Lattice l = c.lattice();
  Words start_state(layer.words() + 1, 0);
  vlayer_mc::placed_start(layer, {l.point(0, 2)}).enumerate(start_state.data(), 0, [] {});
  start_state.resize(layer.words());
  CHECK(broken(c, layer, start_state).empty()); // nothing known yet: every clause holds

  // Robot 0 at (1, 1) in region 0, everything in step with RW at phase 3.
  Words s = start_state;
  set(layer, s, "RW.now", 3);
  set(layer, s, "RW.loc[0]", l.point(1, 1));
  set(layer, s, "CN_0.cn.x", l.point(1, 1));
  set(layer, s, "CN_0.cn.clock", 3);
  set(layer, s, "VBcast.reg[0]", 0);
  CHECK(broken(c, layer, s).empty());

  Words t = s; // (4a): the dead reckoning is off
  set(layer, t, "RW.loc[0]", l.point(2, 1));
  CHECK(broken(c, layer, t) == Clauses{"(4a) CN_0"});
  t = s;
  set(layer, t, "CN_0.cn.clock", 4);
  CHECK(broken(c, layer, t) == Clauses{"(4a) CN_0"});

  t = s; // (3): v_p must be RW.vel(p) or ⊥
  set(layer, t, "CN_0.cn.v", l.point(4, 1));
  CHECK(broken(c, layer, t) == Clauses{"(3) CN_0"});

  t = s; // (4b): the target (4, 1) is 3 away; at phase 3, 4·(3 − 1) = 8 > 3
  set(layer, t, "CN_0.cn.target", l.point(4, 1));
  CHECK(broken(c, layer, t).empty());
  set(layer, t, "RW.now", 5); // at phase 5: 4·(1 − 1) = 0
  set(layer, t, "CN_0.cn.clock", 5);
  CHECK(broken(c, layer, t) == Clauses{"(4b) CN_0"});

  t = s; // (4c): reg may lag only in the window (2, 6) of phases
  set(layer, t, "VBcast.reg[0]", 1);
  CHECK(broken(c, layer, t).empty());
  set(layer, t, "RW.now", 1);
  set(layer, t, "CN_0.cn.clock", 1);
  CHECK(broken(c, layer, t) == Clauses{"(4c) CN_0"});

  t = s; // (2): a VSA's clock is now or ⊥, and M ≠ ∅ only in phases (0, 2]
  set(layer, t, "VN_0.clock", 2);
  CHECK(broken(c, layer, t) == Clauses{"(2) VN_0"});
  set(layer, t, "VN_0.clock", 3);
  set(layer, t, "VN_0.M[0]", l.point(1, 1));
  CHECK(broken(c, layer, t) == Clauses{"(2) VN_0"});
  set(layer, t, "RW.now", 1);
  set(layer, t, "VN_0.clock", 1);
  set(layer, t, "CN_0.cn.clock", 1);
  set(layer, t, "VBcast.reg[0]", 0);
  CHECK(broken(c, layer, t).empty());
}

// Finding F1 (README): as printed, clause (2) is broken by a reachable state — a cn-update
// vcast at phase 0 and delivered at once, after the VSA's time(0) — so L1MC is not closed.
// With the window closed at 0, every reachable state of the smallest instance is in L1MC.
TEST_CASE("vlayer L1MC: every reachable state of the smallest instance (finding F1)", "[vlayer]") {
  const vlayer_mc::VlConfig c;
  const auto unplaced = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const auto layer =
      tioa::Start(unplaced, vlayer_mc::placed_start(unplaced, {c.lattice().point(0, 2)}));
  const auto printed = checker::check_invariant(layer, vlayer_mc::l1mc(c, layer), {});
  CHECK(printed.verdict == checker::Verdict::violated);
  REQUIRE(printed.trace);
  CHECK(printed.trace->steps.size() == 6); // the start and 5 steps, all at time 0
  CHECK(printed.trace->steps.back().action == "vrcv_cn_update_0(0,10)");
  const auto closed =
      checker::check_invariant(layer, vlayer_mc::l1mc(c, layer, vlayer_mc::MWindow::closed), {});
  CHECK(closed.verdict == checker::Verdict::holds);
  CHECK(closed.states == 2'706);
}

// The symbolic check builds L1MC from its conjuncts: on random states (every variable at a
// random code) of 1x2 with two robots, each window, their conjunction is L1MC, and a state
// outside L1MC breaks exactly the conjuncts l1mc_clauses names.
TEST_CASE("vlayer L1MC: the conjuncts together are L1MC", "[vlayer]") {
  vlayer_mc::VlConfig c;
  c.robots = 2;
  const auto layer = vlayer_mc::vlayer(c, {.robots = true, .vsas = true});
  std::mt19937_64 random(7);
  for (const auto window : {vlayer_mc::MWindow::as_printed, vlayer_mc::MWindow::closed}) {
    const auto whole = vlayer_mc::l1mc(c, layer, window);
    const auto clauses = vlayer_mc::l1mc_clauses(c, layer, window);
    const auto conjuncts = vlayer_mc::l1mc_conjuncts(c, layer, window);
    REQUIRE(conjuncts.size() == 2 + 2 * 4); // (2) per region, (3)-(4c) per robot
    int inside = 0, outside = 0;
    for (int n = 0; n < 20000; ++n) {
      Words s(layer.words() + 1, 0);
      tioa::State state(s.data(), 0);
      for (const auto& v : layer.layout().variables())
        state.set_code(v.slot(),
                       std::uniform_int_distribution<std::uint64_t>(0, v.code_count() - 1)(random));
      // Often every node in step with RW, so that the later clauses are reached too.
      if (n % 2 == 0)
        for (const auto& v : layer.layout().variables())
          if (v.name.find("clock") != std::string::npos)
            state.set_code(v.slot(), state.code(layer.layout().find("RW.now")->slot()));
      std::size_t broken_conjuncts = 0;
      for (const auto& conjunct : conjuncts)
        broken_conjuncts += conjunct(state) ? 0 : 1;
      const bool in = whole(state);
      CHECK(in == (broken_conjuncts == 0));
      CHECK(clauses(state).size() == broken_conjuncts);
      (in ? inside : outside) += 1;
    }
    CHECK(inside > 0);
    CHECK(outside > 0);
  }
}
