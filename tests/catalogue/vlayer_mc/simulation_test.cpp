// R_MC (seed 000 §7.3) on hand-made pairs of VLayer[MC] states, part by part, and the checks
// of Lemmas 7.6 and 7.7 (proofs/lemma_7_6.hpp, proofs/lemma_7_7.hpp) on the smallest instances: one
// robot, the cheap constants of VlConfig, 1×1 and 1×2 grids.
#include <catch2/catch.hpp>

#include "models/vlayer_mc/lmc.hpp"
#include "models/vlayer_mc/rw.hpp"
#include "models/vlayer_mc/vlayer.hpp"
#include "proofs/lemma_7_6.hpp"
#include "proofs/lemma_7_7.hpp"
#include "tests/catalogue/vlayer_mc/vl_results.hpp"
#include "tests/models/vlayer_mc/vl_helpers.hpp"

using namespace vl_test;

namespace {

using Conditions = std::vector<std::string>;

struct Pairs {
  vlayer_mc::VlConfig c;
  tioa::Automaton layer = vlayer_mc::vlayer(c, {.robots = true, .vsas = true});
  vlayer_mc::RmcRelation loose{c, layer, vlayer_mc::RmcReading::loose};
  vlayer_mc::RmcRelation strict{c, layer, vlayer_mc::RmcReading::strict};

  // A reset state: robot 0 standing on its target at point `at`, phase 0, VSA clocks 0.
  Words reset(int at) const {
    Words s(layer.words() + 1, 0);
    vlayer_mc::placed_start(layer, {at}).enumerate(s.data(), 0, [] {});
    s.resize(layer.words());
    set(layer, s, "CN_0.cn.x", at);
    set(layer, s, "CN_0.cn.target", at);
    set(layer, s, "CN_0.cn.v", vlayer_mc::zero_velocity);
    set(layer, s, "CN_0.cn.clock", 0);
    set(layer, s, "RW.vel[0]", vlayer_mc::zero_velocity);
    set(layer, s, "VBcast.reg[0]", c.lattice().region_of(at));
    set(layer, s, "VN_0.clock", 0);
    set(layer, s, "VN_1.clock", 0);
    return s;
  }
  Conditions broken(const Words& x, const Words& y) const {
    return loose.broken(pad(x).data(), pad(y).data());
  }
  bool related(const Words& x, const Words& y) const {
    const bool r = loose.related(pad(x).data(), pad(y).data());
    CHECK(r == broken(x, y).empty());
    if (r) // related states have equal keys (the index of lemma-7.7)
      CHECK(loose.key(pad(x).data()) == loose.key(pad(y).data()));
    return r;
  }
  bool strictly_related(const Words& x, const Words& y) const {
    return strict.related(pad(x).data(), pad(y).data());
  }
  static Words pad(Words s) {
    s.push_back(0);
    return s;
  }
};

vlayer_mc::VlConfig grid(int cols) {
  vlayer_mc::VlConfig c;
  c.cols = cols;
  return c;
}

} // namespace

TEST_CASE("vlayer R_MC: a state is related to itself, and each part can break it", "[vlayer]") {
  const Pairs t;
  const int at = t.c.lattice().point(1, 1);
  const Words x = t.reset(at);
  CHECK(t.related(x, x));
  CHECK(t.strictly_related(x, x));

  Words y = x; // (1) real time and locations
  set(t.layer, y, "RW.loc[0]", at + 1);
  CHECK(t.broken(x, y) == Conditions{"(1) RW.loc[0]"});
  y = x;
  set(t.layer, y, "RW.now", 1);
  CHECK(t.broken(x, y) == Conditions{"(1) RW.now"});

  y = x; // (2) GPSupdate records
  set(t.layer, y, "RW.gps_age[0]", 0);
  CHECK(t.broken(x, y) == Conditions{"(2) RW.gps_age[0]"});

  y = x; // (3) VW's state
  set(t.layer, y, "VW.age[1]", 0);
  CHECK(t.broken(x, y) == Conditions{"(3) VW.age[1]"});

  y = x; // (4) Vbcast's last recorded region
  set(t.layer, y, "VBcast.reg[0]", bottom);
  CHECK(t.broken(x, y) == Conditions{"(4) VBcast.reg[0]"});

  // (4) a message in flight: compared while pending; an empty slot's leftovers are not (D18)
  Words x2 = x;
  set(t.layer, x2, "VBcast.cn_pending[0]", 1);
  set(t.layer, x2, "VBcast.cn_loc[0]", at);
  y = x2;
  set(t.layer, y, "VBcast.cn_loc[0]", at + 1);
  CHECK(t.broken(x2, y) == Conditions{"(4) VBcast.cn_loc[0]"});
  set(t.layer, y, "VBcast.cn_pending[0]", 0);
  CHECK(t.broken(x2, y) == Conditions{"(4) VBcast.cn_pending[0]"});
  y = x;
  set(t.layer, y, "VBcast.cn_loc[0]", at + 1);
  set(t.layer, y, "VBcast.tu_target[1]", 3);
  set(t.layer, y, "VBcast.vn_count[0]", 1);
  CHECK(t.related(x, y));

  y = x; // (5) the nodes: a VSA's clock, a client's state, `failed`
  set(t.layer, y, "VN_1.clock", bottom);
  CHECK(t.broken(x, y) == Conditions{"(5) VN_1.clock"});
  y = x;
  set(t.layer, y, "VN_0.V[1]", 1);
  CHECK(t.broken(x, y) == Conditions{"(5) VN_0.V[1]"});
  y = x;
  set(t.layer, y, "CN_0.cn.clock", 1);
  CHECK(t.broken(x, y) == Conditions{"(5) CN_0.cn.clock"});
  y = x;
  set(t.layer, y, "CN_0.failed", 1);
  CHECK(t.broken(x, y) == Conditions{"(5) CN_0.failed"});
  x2 = x; // failed in both: the frozen state is not compared (D19)
  set(t.layer, x2, "CN_0.failed", 1);
  set(t.layer, y, "CN_0.cn.x", bottom);
  CHECK(t.related(x2, y));
  y = x; // VBDelay's leftovers when it holds nothing (D19)
  set(t.layer, y, "CN_0.delay.loc", at);
  CHECK(t.related(x, y));
  set(t.layer, y, "CN_0.delay.held", 1);
  CHECK(t.broken(x, y) == Conditions{"(5) CN_0.delay.held"});
}

TEST_CASE("vlayer R_MC part (2): y's velocity ⊥ follows x only while x's robot stands (D17)",
          "[vlayer]") {
  const Pairs t;
  const int at = t.c.lattice().point(1, 1);
  Words x = t.reset(at);
  // Nothing urgent, so that time can pass: the cn-update sent, GPS and time updates done.
  set(t.layer, x, "CN_0.cn.since", 0);
  set(t.layer, x, "RW.gps_age[0]", 0);
  set(t.layer, x, "VW.age[0]", 0);
  set(t.layer, x, "VW.age[1]", 0);
  Words y = x;
  set(t.layer, y, "RW.vel[0]", bottom);
  CHECK(t.related(x, y));       // x: 0, y: ⊥, both stand
  CHECK_FALSE(t.related(y, x)); // x: ⊥, y: 0 — not the paper's direction
  Words moving = x;
  set(t.layer, moving, "RW.vel[0]", at + 1);
  CHECK(t.broken(moving, y) == Conditions{"(2) RW.vel[0]"});
  // Why: as printed, (2) would relate them, but one tick moves x's robot and not y's.
  const Words x1 = after(t.layer, moving, "tick");
  const Words y1 = after(t.layer, y, "tick");
  CHECK(get(t.layer, x1, "RW.loc[0]") != get(t.layer, y1, "RW.loc[0]"));
}

TEST_CASE("vlayer R_MC loose reading: the target while the cn-update is due (D20)", "[vlayer]") {
  const Pairs t;
  const int at = t.c.lattice().point(1, 1);
  const Words x = t.reset(at); // standing on its target, cn-update due
  Words y = x;
  set(t.layer, y, "CN_0.cn.target", bottom);
  CHECK(t.related(x, y));
  CHECK_FALSE(t.strictly_related(x, y));
  CHECK(t.strict.broken(Pairs::pad(x).data(), Pairs::pad(y).data()) ==
        Conditions{"(5) CN_0.cn.target"});
  // Both vcast the cn-update and set x* := ⊥: the same state.
  const std::string vcast = "vcast_cn_update_0(" + std::to_string(at) + ")";
  CHECK(after(t.layer, x, vcast) == after(t.layer, y, vcast));
  // A target elsewhere would be steered to: not related.
  Words far = x;
  set(t.layer, far, "CN_0.cn.target", at + 1);
  CHECK(t.broken(far, y) == Conditions{"(5) CN_0.cn.target"});
  // Not due (clock 1): the targets are compared.
  Words x1 = x, y1 = y;
  set(t.layer, x1, "CN_0.cn.clock", 1);
  set(t.layer, y1, "CN_0.cn.clock", 1);
  set(t.layer, x1, "RW.now", 1);
  set(t.layer, y1, "RW.now", 1);
  CHECK(t.broken(x1, y1) == Conditions{"(5) CN_0.cn.target"});
}

TEST_CASE("vlayer R_MC accounts for every variable of VLayer[MC]", "[vlayer]") {
  // The constructor throws when a variable has no part; 2 robots and 2×2 grids as well.
  vlayer_mc::VlConfig c;
  c.rows = 2;
  c.robots = 2;
  const auto layer = vlayer_mc::vlayer(c, {});
  CHECK_NOTHROW(vlayer_mc::RmcRelation(c, layer));
}

// Lemma 7.7 on 1×1 (Reach: 1 069 450 states with failures, ~4 s; 1 055 530 with cn_repair,
// which drops stale targets after a restart; the family: 36 states).
// Finding F4: with part (4) as printed, the 9 family states with an unknown robot (reg ⊥)
// and VN clock 0 have no related reachable state; D21 relates all 36.
// [slow]: over 10 s under the sanitizers (tools/run-tests.sh skips it there).
TEST_CASE("vlayer lemma-7.7 on 1x1: F4, 9 family states unmatched as printed", "[vlayer][slow]") {
  const vlayer_mc::VlConfig c = grid(1);
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const auto r = vlayer_mc::check_lemma_7_7(c, layer, vlayer_mc::MWindow::closed, {});
  INFO(r.message);
  CHECK(r.verdict == checker::Verdict::violated);
  CHECK(r.states == 1'069'450);
  CHECK(r.coverage.starts == checker::Starts::sampled); // the family, a part of ResetMC
  CHECK(r.coverage.count == 36);
  CHECK(figure(r, "matched (strict)") == "15 of 36");
  CHECK(figure(r, "matched (loose)") == "27 of 36");
  CHECK(figure(r, "matched (loose-reg)") == "36 of 36");
  CHECK(figure(r, "related pairs") == "277");
  CHECK_THAT(r.message, Catch::StartsWith("9 of the 36 ResetMC states"));
  CHECK_THAT(r.message, Catch::EndsWith("breaks (5) VN_0.clock"));
  REQUIRE(r.trace);
  REQUIRE(r.trace->steps.size() == 1); // the unmatched family state: robot unknown, VN clock 0
  const Words x = r.trace->steps.front().state;
  CHECK(get(layer, x, "CN_0.cn.x") == std::nullopt);
  CHECK(get(layer, x, "VBcast.reg[0]") == std::nullopt);
  CHECK(get(layer, x, "VN_0.clock") == 0);
  CHECK(get(layer, x, "VW.age[0]") == c.eps_sample);
}

// Lemma 7.6 on 1×1 from the 277 initial pairs of the loose reading: holds on the pairs
// reached (run_property makes it incomplete: a simulation relation is a claim on every pair).
TEST_CASE("vlayer lemma-7.6 on 1x1: R_MC is a simulation on the pairs reached", "[vlayer]") {
  const vlayer_mc::VlConfig c = grid(1);
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const auto r = vlayer_mc::check_lemma_7_6(c, layer, vlayer_mc::MWindow::closed, {});
  INFO(r.message);
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(r.coverage.starts == checker::Starts::sampled);
  CHECK(r.coverage.count == 4'630);
  CHECK(figure(r, "initial pairs") == "277");
  CHECK(r.states == 4'630);
  CHECK(r.edges == 8'787);
}

// The same from the 365 initial pairs of the loose-reg reading (D21): holds.
TEST_CASE("vlayer lemma-7.6 on 1x1, loose-reg reading: holds", "[vlayer]") {
  const vlayer_mc::VlConfig c = grid(1);
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  const auto r = vlayer_mc::check_lemma_7_6(c, layer, vlayer_mc::MWindow::closed, {},
                                            vlayer_mc::RmcReading::loose_reg);
  INFO(r.message);
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(figure(r, "initial pairs") == "365");
  CHECK(r.states == 5'440);
}

TEST_CASE("vlayer lemma-7.6/7.7: a state limit gives incomplete, never holds", "[vlayer]") {
  const vlayer_mc::VlConfig c; // 1×2
  const auto layer = vlayer_mc::vlayer(c, {.robots = false, .vsas = false});
  checker::ExploreOptions o;
  o.limits.max_states = 10'000;
  CHECK(vlayer_mc::check_lemma_7_7(c, layer, vlayer_mc::MWindow::closed, o).verdict ==
        checker::Verdict::incomplete);
  CHECK(vlayer_mc::check_lemma_7_6(c, layer, vlayer_mc::MWindow::closed, o).verdict ==
        checker::Verdict::incomplete);
}
