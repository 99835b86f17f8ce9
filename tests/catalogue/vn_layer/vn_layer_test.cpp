// The properties of `vn-layer` (models/vn_layer/README.md) on 2×1 with 2 CNs, δ = 13: the
// paper's layer meets its timing claims and (Y) when δ meets the lattice's rule, and each
// reading or shorter round that breaks one shows it with a trace that replays. Counts
// pinned (of the full graph: these runs do not ask for the zero-time reduction).
#include <catch2/catch.hpp>

#include "catalogue/registry.hpp"
#include "catalogue/vn_layer.hpp"
#include "checker/property.hpp"
#include "checker/trace.hpp"
#include "proofs/vn_layer/round_refinement.hpp"
#include "proofs/vn_layer/stabilisation.hpp"

namespace vn_layer_test {

struct Run {
  checker::PropertyResult result;
  tioa::Automaton system;
};

Run run(const std::string& property, const std::vector<std::string>& settings) {
  const catalogue::ModelDefinition def = catalogue::vn_layer_definition();
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, settings));
  for (const auto& p : m.properties)
    if (p.name == property)
      return {checker::run_property(m.system, p, {}), m.system};
  FAIL("no property " << property);
  return {{}, m.system};
}

// The figure `name` of a report, or "(none)".
std::string figure(const checker::PropertyResult& r, const std::string& name) {
  for (const auto& [key, value] : r.figures)
    if (key == name)
      return value;
  return "(none)";
}

bool has_note(const checker::PropertyResult& r, const std::string& text) {
  for (const auto& note : r.notes)
    if (note.find(text) != std::string::npos)
      return true;
  return false;
}

// Violated, with a trace of the model that replays and ends where `clause` fails.
void check_counterexample(const Run& run, const std::string& clause) {
  const checker::PropertyResult& r = run.result;
  CHECK(r.verdict == checker::Verdict::violated);
  REQUIRE(r.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(run.system), *r.trace, &why));
  INFO(why);
  CHECK(has_note(r, "the last state breaks " + clause));
}

} // namespace vn_layer_test

namespace vt = vn_layer_test;

TEST_CASE("vn-layer 2x1, every placement: no time-lock, round timing and (Y) hold", "[vn-layer]") {
  for (const char* property : {"no-timelock", "round-timing", "y-consistency"}) {
    INFO(property);
    const auto r = vt::run(property, {}).result;
    CHECK(r.verdict == checker::Verdict::holds);
    CHECK(r.states == 105'854);
    CHECK(r.edges == 191'649);
    CHECK(r.coverage.count == 225); // 15 points, 2 CNs
    CHECK(vt::has_note(r, "delta = 13 meets the paper's round-length rule (seed 002 §V-B: delta > "
                          "11.05) and meets the lattice's (delta > 12"));
  }
}

TEST_CASE("vn-layer counts from the corner: 1x1, 1x2 and 2x1", "[vn-layer]") {
  CHECK(vt::run("no-timelock", {"start=corner"}).result.states == 737);
  CHECK(vt::run("no-timelock", {"start=corner", "rows=1"}).result.states == 586);
  CHECK(vt::run("no-timelock", {"start=corner", "rows=1", "cols=2"}).result.states == 822);
}

TEST_CASE("vn-layer delta = 12 meets the paper's rule but not the lattice's: a VN restarts "
          "too late",
          "[vn-layer]") {
  // The CN sent to o_0 enters zone 0 only on the step that lands it there (half-open
  // zones), and VN_0 may take d_r more: at 9 + 2 + 1 = 12 = δ it is not yet alive.
  const vt::Run r = vt::run("round-timing", {"start=corner", "delta=12"});
  vt::check_counterexample(r, "(T4) VN_0 is failed at a round start with CN_0 in its zone");
  CHECK(r.result.trace->steps.back().time == 24);
  CHECK(vt::has_note(r.result, "delta = 12 meets the paper's round-length rule"));
  CHECK(vt::has_note(r.result, "breaks the lattice's (delta > 12"));
  CHECK(vt::run("y-consistency", {"start=corner", "delta=12"}).result.verdict ==
        checker::Verdict::holds);
}

TEST_CASE("vn-layer delta = 10 breaks both rules, and (Y) with them", "[vn-layer]") {
  vt::check_counterexample(vt::run("y-consistency", {"start=corner", "delta=10"}),
                           "(Y) VN_0 and VN_1 computed the same round with y(1) = 0 and 2");
}

TEST_CASE("vn-layer eps = 0: a cn-update can arrive after the exchange-trigger (C14)",
          "[vn-layer]") {
  vt::check_counterexample(vt::run("round-timing", {"start=corner", "eps=0"}),
                           "(T1) a cn-update reached VN_1 after its exchange-trigger");
  vt::check_counterexample(vt::run("y-consistency", {"start=corner", "eps=0"}),
                           "(Y) VN_0 and VN_1");
}

TEST_CASE("vn-layer vn_fail=any: a VN that fails with CNs in its zone breaks (Y) (C10)",
          "[vn-layer]") {
  vt::check_counterexample(vt::run("y-consistency", {"start=corner", "vn_fail=any"}),
                           "(Y) VN_0 and VN_1 computed the same round with y(1) = 0 and 1");
  // Only while its zone is empty (the emulation), no VN of this instance ever fails.
  CHECK(vt::run("y-consistency", {"vn_fail=never"}).result.states == 105'854);
}

TEST_CASE("vn-layer: a CN that fails and recovers can send twice in one instant, past the "
          "model's bound",
          "[vn-layer]") {
  const auto r =
      vt::run("y-consistency", {"start=corner", "rows=1", "cols=1", "cns=1", "cn_faults=1"}).result;
  CHECK(r.verdict == checker::Verdict::incomplete);
  CHECK_THAT(r.message, Catch::Contains("one message per kind and sender in VLBcast"));
}

TEST_CASE("vn-layer cn-reports: with cn_fail=keep a CN that fails before its cn-update and "
          "recovers within the round is silent for ever (V5)",
          "[vn-layer]") {
  const auto holds = vt::run("cn-reports", {}).result;
  CHECK(holds.verdict == checker::Verdict::holds);
  CHECK(holds.states == 105'854);
  const std::vector<std::string> one_cn = {"start=corner", "rows=1", "cols=1", "cns=1",
                                           "cn_faults=1"};
  std::vector<std::string> keep = one_cn;
  keep.push_back("cn_fail=keep");
  const vt::Run silent = vt::run("cn-reports", keep);
  vt::check_counterexample(silent, "(R) CN_0 is active with round in a past round");
  // init at time 0, fail before the cn-update, recover within round 0, the tick into round 1.
  REQUIRE(silent.result.trace);
  CHECK(silent.result.trace->steps.back().time == 13);
  CHECK(vt::has_note(silent.result, "cn_fail=keep"));
  // Resetting (seed 002 line 35) leaves no counter behind; the run meets the model's bound.
  const auto reset = vt::run("cn-reports", one_cn).result;
  CHECK(reset.verdict == checker::Verdict::incomplete);
  CHECK_THAT(reset.message, Catch::Contains("one message per kind and sender in VLBcast"));
}

// The VNs compute targets with vlayer-mc's assign and calctarget (C18, C19), and every report
// counts the branches of seed 002 Fig. 7 they take, as vlayer-mc's do: with both CNs at one
// corner off the curve, the boundary branch sends one of them towards the curve.
TEST_CASE("vn-layer reports count the branches of Fig. 7", "[vn-layer]") {
  const auto r = vt::run("y-consistency", {"start=corner"}).result;
  CHECK(vt::figure(r, "Fig. 7 computations (distinct)") == "4");
  CHECK(vt::figure(r, "Fig. 7 lines 19-22 boundary, reassigning") == "1");
  CHECK(vt::figure(r, "Fig. 7 lines 30-31 robots to a neighbour's centre") == "1");
  CHECK(vt::figure(r, "Fig. 7 lines 7-12 on the curve, reassigning") == "0");
}

// round-refinement's reference: assign per zone on the counts of a round start. On 2×1 (zone
// 0 on the curve, zone 1 below it) the boundary branch sends ⌊(y − e)/|In|⌋ = 1 of two CNs
// in zone 1 to zone 0; a zone on the curve with nobody lower keeps its CNs.
TEST_CASE("vn-layer: the round-level counts one round later", "[vn-layer]") {
  vn_layer::VnConfig c;
  CHECK(vn_layer::counts_after_round(c, {0, 2}) == std::vector<int>{1, 1});
  CHECK(vn_layer::counts_after_round(c, {1, 1}) == std::vector<int>{1, 1});
  CHECK(vn_layer::counts_after_round(c, {2, 0}) == std::vector<int>{2, 0});
  c.rows = 1;
  CHECK(vn_layer::counts_after_round(c, {2}) == std::vector<int>{2});
}

// stabilisation's reference: from (0, 2) the counts are (0, 2) at the layer's rounds 0 and
// 1 (round 0 skipped) and (1, 1) from round 2 on; (1, 1) and (2, 0) never change.
TEST_CASE("vn-layer: the round-level T_stab in the layer's numbering", "[vn-layer]") {
  const vn_layer::VnConfig c;
  CHECK(vn_layer::round_level_t_stab(c, {0, 2}) == 2);
  CHECK(vn_layer::round_level_t_stab(c, {1, 1}) == 0);
  CHECK(vn_layer::round_level_t_stab(c, {2, 0}) == 0);
}

// position-refinement's reference: assign and calctarget per zone on the points of a round
// start. On 2×1 from the corner (0, 4), one of the two CNs in zone 1 goes to o_0 = (1, 1)
// (line 31, the lowest id) and the other stays (Γ_1 is empty). On 1×2 two CNs off the curve
// go to its nearest point (line 33); two on it at (0, 1) go to the ends of Γ_0 (lines
// 35–36), the second to (2, 1), which zone 1 owns (V4).
TEST_CASE("vn-layer: the CNs' points one round later", "[vn-layer]") {
  vn_layer::VnConfig c;
  const vn_layer::Lattice tall = c.lattice();
  CHECK(vn_layer::positions_after_round(c, {tall.point(0, 4), tall.point(0, 4)}) ==
        std::vector<int>{tall.point(1, 1), tall.point(0, 4)});
  c.rows = 1;
  c.cols = 2;
  const vn_layer::Lattice wide = c.lattice();
  CHECK(vn_layer::positions_after_round(c, {wide.point(0, 2), wide.point(0, 2)}) ==
        std::vector<int>{wide.point(0, 1), wide.point(0, 1)});
  CHECK(vn_layer::positions_after_round(c, {wide.point(0, 1), wide.point(0, 1)}) ==
        std::vector<int>{wide.point(0, 1), wide.point(2, 1)});
  c.owned_ends = true; // the end zone 0 owns: (1, 1)
  CHECK(vn_layer::positions_after_round(c, {wide.point(0, 1), wide.point(0, 1)}) ==
        std::vector<int>{wide.point(0, 1), wide.point(1, 1)});
  // A failed CN is nobody's.
  CHECK(vn_layer::positions_after_round(c, {-1, wide.point(0, 2)}) ==
        std::vector<int>{-1, wide.point(0, 1)});
}

// position-refinement follows V4's migration, and sees the move a late VN restart drops.
TEST_CASE("vn-layer position-refinement: the layer follows the position-level round system "
          "across borders, and a VN restarted after the cn-update drops a move",
          "[vn-layer]") {
  for (const auto& settings : std::vector<std::vector<std::string>>{
           {}, {"start=corner", "rows=1", "cols=2"}, {"rows=1", "cols=2"}}) {
    const auto r = vt::run("position-refinement", settings).result;
    CHECK(r.verdict == checker::Verdict::holds);
  }
  const vt::Run late = vt::run("position-refinement", {"start=corner", "delta=12"});
  CHECK(late.result.verdict == checker::Verdict::violated);
  CHECK_THAT(late.result.message,
             Catch::Contains("a round starts with the points of the CNs ((1, 1), (0, 4)) where "
                             "the position-level round system gives ((0, 1), (0, 4))"));
  REQUIRE(late.result.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(late.system), *late.result.trace, &why));
  INFO(why);
  CHECK(vt::run("position-refinement", {"start=corner", "cn_faults=1"}).result.verdict ==
        checker::Verdict::incomplete);
}

TEST_CASE("vn-layer round-refinement: the layer follows the round-level system on 2x1, and "
          "leaves it where calctarget sends a CN across a border",
          "[vn-layer]") {
  {
    const auto r = vt::run("round-refinement", {}).result;
    CHECK(r.verdict == checker::Verdict::holds);
    CHECK(r.states == 105'854);
    CHECK(r.coverage.count == 225);
    CHECK(vt::figure(r, "round starts") == "1350");
    CHECK(vt::figure(r, "rounds checked") == "2025");
  }
  // 1×2: calctarget's line 36 sends the second CN to the far end of Γ_0, which zone 1 owns
  // (V4): the next round starts with (1, 1) where assign moved nobody.
  const vt::Run across = vt::run("round-refinement", {"start=corner", "rows=1", "cols=2"});
  CHECK(across.result.verdict == checker::Verdict::violated);
  CHECK_THAT(across.result.message,
             Catch::Contains("a round starts with the counts (1, 1) where the round-level "
                             "system gives (2, 0) from the counts (2, 0)"));
  REQUIRE(across.result.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(across.system), *across.result.trace, &why));
  INFO(why);
  CHECK(across.result.trace->length() == 90);
  CHECK(across.result.trace->steps.back().action == "tick");
  // Aiming at the ends zone 0 owns (owned_ends=1, vlayer-mc's D14) keeps the layer on it.
  CHECK(vt::run("round-refinement", {"start=corner", "rows=1", "cols=2", "owned_ends=1"})
            .result.verdict == checker::Verdict::holds);
  // Below both round rules the CN sent to zone 0 is not there when the round starts.
  CHECK_THAT(vt::run("round-refinement", {"start=corner", "delta=10"}).result.message,
             Catch::Contains("the counts (0, 2) where the round-level system gives (1, 1)"));
  const auto faults = vt::run("round-refinement", {"start=corner", "cn_faults=1"}).result;
  CHECK(faults.verdict == checker::Verdict::incomplete);
  CHECK_THAT(faults.message, Catch::Contains("not checked: with cn_faults=1"));
}

// round-timing's measured figures: every bound of §V-B is met with no slack on the lattice,
// and a CN reaches its target two quanta before the round ends (then VN_0 takes d_r = 1 to
// restart: δ = 12 leaves none, V1).
TEST_CASE("vn-layer round-timing: the worst times against the stated ones", "[vn-layer]") {
  const auto figures = [](const std::vector<std::string>& settings) {
    const auto r = vt::run("round-timing", settings).result;
    CHECK(r.verdict == checker::Verdict::holds);
    std::vector<std::string> out;
    for (const char* name : {"cn-update delivered", "vn-update delivered",
                             "target-update after its trigger", "CN on target"})
      for (const char* which : {" measured", " stated"})
        for (const auto& [key, value] : r.figures)
          if (key == std::string(name) + which)
            out.push_back(value);
    return out;
  };
  CHECK(figures({}) == std::vector<std::string>{"1", "1 (d_v)", "5", "5 (d_MMT + 3d_v + eps)", "3",
                                                "3 (d_MMT + 2d_v)", "11", "13 (delta)"});
  CHECK(figures({"start=corner", "d_v=2", "delta=20"}) ==
        std::vector<std::string>{"2", "2 (d_v)", "8", "8 (d_MMT + 3d_v + eps)", "5",
                                 "5 (d_MMT + 2d_v)", "16", "20 (delta)"});
  // A run that breaks a clause stops early: it measures nothing.
  const auto broken = vt::run("round-timing", {"start=corner", "delta=12"}).result;
  for (const auto& [key, value] : broken.figures)
    CHECK(key.find("measured") == std::string::npos);
}

// stabilisation (Theorem 1, 002:234 and 002:302) measured round by round. On 2×1 every
// execution settles by round 2 as the round-level system does from the same counts, and a
// CN of C_in may still be off Γ at T_stab + 1 (the VNs skip round 0, C12), never at
// T_stab + 2. A VN that may fail with CNs in its zone (vn_fail=any, C10) can keep a CN off
// Γ for ever: the claim of 002:302 fails, with a lasso.
TEST_CASE("vn-layer stabilisation: the assignment settles and C_in is on the curve by "
          "T_stab + 2, unless a VN may fail for ever",
          "[vn-layer]") {
  {
    const auto r = vt::run("stabilisation", {}).result;
    CHECK(r.verdict == checker::Verdict::holds);
    CHECK(r.states == 105'854);
    CHECK(r.coverage.count == 225);
    CHECK(vt::figure(r, "round starts") == "1350");
    CHECK(vt::figure(r, "T_out (worst)") == "2");
    CHECK(vt::figure(r, "T_stab (worst)") == "2");
    CHECK(vt::figure(r, "starts where T_stab = the round-level system's") == "225 of 225");
    CHECK(vt::figure(r, "C_in on Gamma from, after T_stab (worst)") == "T_stab + 2");
    // Lemma 6: two CNs settle in one zone of the curve or one per zone; 10·3/(2·9/10).
    CHECK(vt::figure(r, "|y_h/q_h - y_g/q_g| from T_stab on (worst)") ==
          "0, bound 10(2m-1)/(q_min rho2) = 50/3");
    CHECK(vt::has_note(r, "proportionality cannot fail on this instance"));
    // Lemma 7: two CNs of a zone stand at its two ends, evenly spaced.
    CHECK(vt::figure(r, "distance to even spacing in the limit (worst, lattice units)") == "0");
    CHECK(vt::figure(r, "CN points fixed from round (worst)") == "3");
  }
  // Three CNs in one zone of side 4: calctarget's point rounded down stops the middle CN at
  // x = 1, where half its distance to the midpoint of its neighbours is below one unit.
  {
    const auto r = vt::run("stabilisation", {"rows=1", "cns=3", "b=4", "start=corner"}).result;
    CHECK(r.verdict == checker::Verdict::holds);
    CHECK(vt::figure(r, "distance to even spacing in the limit (worst, lattice units)") ==
          "1 (zone 0: CNs at x = 0, 1, 4, evenly spaced at x = 0, 2, 4)");
    CHECK(vt::figure(r, "CN points fixed from round (worst)") == "4");
  }
  // 1×2: the migration of V4 moves a CN across the border a round after the counts settle.
  {
    const auto r = vt::run("stabilisation", {"rows=1", "cols=2"}).result;
    CHECK(r.verdict == checker::Verdict::holds);
    CHECK(vt::figure(r, "T_stab (worst)") == "3");
    CHECK(vt::figure(r, "starts where T_stab = the round-level system's") == "189 of 225");
    CHECK(vt::has_note(r, "on 36 start states the worst T_stab differs"));
  }
  const vt::Run failing = vt::run("stabilisation", {"vn_fail=any", "cns=1"});
  const checker::PropertyResult& r = failing.result;
  CHECK(r.verdict == checker::Verdict::violated);
  CHECK_THAT(r.message, Catch::Contains("with a CN of C_in off Gamma at the start of round 2 (2 "
                                        "rounds after T_stab"));
  CHECK(vt::figure(r, "C_in on Gamma from round (worst)") == "unbounded");
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "lasso");
  CHECK(r.trace->loop_start);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(failing.system), *r.trace, &why));
  INFO(why);

  const auto faults = vt::run("stabilisation", {"start=corner", "cn_faults=1"}).result;
  CHECK(faults.verdict == checker::Verdict::incomplete);
  CHECK_THAT(faults.message, Catch::Contains("not checked: Theorem 1 assumes"));
}

TEST_CASE("vn-layer round-closure: L_round is reached at delta, closed from round to round and "
          "free of time-locks on 2x1; delta = 12 leaves it",
          "[vn-layer]") {
  const auto r = vt::run("round-closure", {}).result;
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(r.states == 113'948);
  CHECK(vt::figure(r, "(a) states of round 0") == "48366");
  CHECK(vt::figure(r, "(a) round starts at time delta") == "900");
  CHECK(vt::figure(r, "(b) L_round classes") == "3600"); // (2 x 15)^2 CNs x 2^2 zones
  CHECK(r.coverage.starts == checker::Starts::all);
  CHECK(r.coverage.count == 3600);

  // V1: the CN reaches a zone whose VN has not restarted by the round start (d_r).
  const auto v = vt::run("round-closure", {"start=corner", "delta=12"}).result;
  CHECK(v.verdict == checker::Verdict::violated);
  CHECK(v.message.find("(b) a round from an L_round state ends outside L_round (R2: CN_0 is "
                       "in zone 0, whose VN is failed)") != std::string::npos);
  REQUIRE(v.trace);
  REQUIRE(v.trace_system);
  CHECK(v.trace_system_name == "L_round");
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(*v.trace_system), *v.trace, &why));
  INFO(why);
  REQUIRE(v.trace_in_legal_set.size() == v.trace->steps.size());
  CHECK(v.trace_in_legal_set.front());
  CHECK_FALSE(v.trace_in_legal_set.back());

  // (a): a VN that may fail with its CN present can be failed at time delta.
  const auto a = vt::run("round-closure", {"cns=1", "vn_fail=any", "start=corner"});
  CHECK(a.result.verdict == checker::Verdict::violated);
  CHECK(a.result.message.find("(a) the round start at time 13 is outside L_round (R2") !=
        std::string::npos);
  REQUIRE(a.result.trace);
  CHECK(checker::replay(tioa::SuccessorGenerator(a.system), *a.result.trace, &why));

  CHECK(vt::run("round-closure", {"start=corner", "cn_faults=1"}).result.verdict ==
        checker::Verdict::incomplete);
}
