// The properties of `vn-emulation` (models/vn_emulation/README.md) on one zone with two
// physical nodes: replica consistency and Theorem 2's figures, the start-up time tight at
// 4d_p + 5ε for three (d_p, ε), and d_v = 2d_p + ε broken with a trace that replays
// (finding E1). Counts pinned (no reduction).
#include <catch2/catch.hpp>

#include "catalogue/registry.hpp"
#include "catalogue/vn_emulation.hpp"
#include "checker/property.hpp"
#include "checker/trace.hpp"
#include "models/vn_emulation/emulation.hpp"
#include "models/vn_emulation/refinement.hpp"

namespace vn_emulation_test {

struct Run {
  checker::PropertyResult result;
  tioa::Automaton system;
};

Run run(const std::string& property, const std::vector<std::string>& settings,
        checker::ExploreOptions options = {}) {
  const catalogue::ModelDefinition def = catalogue::vn_emulation_definition();
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, settings));
  for (const auto& p : m.properties)
    if (p.name == property)
      return {checker::run_property(m.system, p, options), m.system};
  FAIL("no property " << property);
  return {{}, m.system};
}

std::string figure(const checker::PropertyResult& r, const std::string& name) {
  for (const auto& [key, value] : r.figures)
    if (key == name)
      return value;
  return "";
}

} // namespace vn_emulation_test

namespace et = vn_emulation_test;

TEST_CASE("vn-emulation, warm start, one message, one fail: replicas agree and every figure "
          "is within Theorem 2's",
          "[vn-emulation]") {
  const auto replicas = et::run("replica-consistency", {}).result;
  CHECK(replicas.verdict == checker::Verdict::holds);
  CHECK(replicas.states == 120'790);
  CHECK(replicas.edges == 383'758);
  const auto theorem = et::run("theorem-2", {}).result;
  CHECK(theorem.verdict == checker::Verdict::holds);
  CHECK(et::figure(theorem, "d_MMT measured") == "2");
  CHECK(et::figure(theorem, "d_v measured") == "3");
  CHECK(et::figure(theorem, "d_v stated") == "3 (2d_p + eps)");
  CHECK(et::run("no-timelock", {}).result.verdict == checker::Verdict::holds);
}

TEST_CASE("vn-emulation, cold start: the VN starts exactly d_r = 4d_p + 5eps after time 0",
          "[vn-emulation]") {
  // (d_p, ε) = (1, 1), (2, 1), (1, 2): 9, 13, 14, the stated figure each time.
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"start=cold", "messages=0", "fails=0"}, "9"},
      {{"start=cold", "messages=0", "fails=0", "d_p=2"}, "13"},
      {{"start=cold", "messages=0", "fails=0", "eps=2"}, "14"}};
  for (const auto& [settings, d_r] : cases) {
    const et::Run r = et::run("theorem-2", settings);
    CHECK(r.result.verdict == checker::Verdict::holds);
    CHECK(et::figure(r.result, "d_r measured") == d_r);
    CHECK(et::figure(r.result, "d_r stated").rfind(d_r + " ", 0) == 0);
    REQUIRE(r.result.trace);
    CHECK(r.result.trace_kind == "worst-case");
    CHECK(checker::replay(tioa::SuccessorGenerator(r.system), *r.result.trace, nullptr));
  }
  CHECK(et::run("theorem-2", {"start=cold", "messages=0", "fails=0"}).result.states == 325);
}

TEST_CASE("vn-emulation E1: with two fails a client message reaches the VN later than "
          "d_v = 2d_p + eps",
          "[vn-emulation][slow][long]") {
  checker::ExploreOptions bounded;
  bounded.limits.max_states = 3'000'000; // the trace is 23 steps deep; the whole space is 16M+
  const et::Run r = et::run("theorem-2", {"fails=2", "inputs=ticks"}, bounded);
  CHECK(r.result.verdict == checker::Verdict::violated);
  CHECK_THAT(r.result.message, Catch::StartsWith("d_v exceeds Theorem 2's 2d_p + eps = 3"));
  REQUIRE(r.result.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(r.system), *r.result.trace, &why));
  INFO(why);
}

TEST_CASE("vn-emulation: a model bound met makes a check incomplete, never holds",
          "[vn-emulation][slow]") {
  // A cold start with a client message fills TOBcast's buffer of 6 at the reset instant.
  const auto r = et::run("replica-consistency", {"start=cold", "messages=1", "fails=0"}).result;
  CHECK(r.verdict == checker::Verdict::incomplete);
  CHECK_THAT(r.message, Catch::Contains("the bound on TOBcast's buffer"));
  CHECK(r.trace_kind == "bound");
}

TEST_CASE("vn-emulation buffer: TOBcast's buffer bound is a parameter; below what the instance "
          "needs the check is incomplete and names it, from 4 on the defaults hold",
          "[vn-emulation]") {
  const auto small = et::run("replica-consistency", {"buffer=3"});
  CHECK(small.result.verdict == checker::Verdict::incomplete);
  CHECK_THAT(small.result.message,
             Catch::Contains("the bound on TOBcast's buffer is met (the trace): raise it "
                             "(-p buffer=N, now 3, at most 8)"));
  REQUIRE(small.result.trace);
  CHECK(small.result.trace_kind == "bound");
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(small.system), *small.result.trace, &why));
  INFO(why);
  const auto enough = et::run("replica-consistency", {"buffer=4"}).result;
  CHECK(enough.verdict == checker::Verdict::holds);
  CHECK(enough.states == 120'790); // as with the default 6: the bound is never met
}

TEST_CASE("vn-emulation refines-vn: the emulation implements the abstract VN on the defaults",
          "[vn-emulation]") {
  const auto r = et::run("refines-vn", {}).result;
  CHECK(r.verdict == checker::Verdict::holds);
  // The monitor's ghosts (the reference replica's val, completed actions, the instant's
  // TOBcast messages) tell apart states the other checks count as one: 120,790 there.
  CHECK(r.states == 132'452);
  const auto cold = et::run("refines-vn", {"start=cold", "messages=0", "fails=0"}).result;
  CHECK(cold.verdict == checker::Verdict::holds);
}

TEST_CASE("vn-emulation refines-vn: the monitor sees a replica that leaves the abstract VN, and "
          "a transmission the VN did not make",
          "[vn-emulation]") {
  vn_emulation::EmuConfig c;
  c.refinement_monitor = true;
  const vn_emulation::Emulation e = vn_emulation::emulation(c);
  const vn_emulation::Slots& slots = *e.slots;
  // The warm start state: both replicas active at the VN's start, as the monitor.
  std::vector<tioa::Word> words(e.automaton.words() + 1, 0), start;
  e.automaton.start().enumerate(words.data(), 0, [&] { start = words; });
  tioa::State s(start.data(), 0);
  CHECK_FALSE(vn_emulation::refinement_failure(slots, s));
  // PN_1 holds a state the abstract VN never reached (nothing to send: time may pass).
  vn_emulation::VnValue other;
  other.count = 1;
  other.last = 0;
  slots.pns[1].value.store(s, other);
  const auto failure = vn_emulation::refinement_failure(slots, s);
  REQUIRE(failure);
  CHECK(failure->find("PN_1") != std::string::npos);
  slots.pns[1].value.store(s, vn_emulation::VnValue{});
  // A VN message no replica's reference executed goes out.
  vn_emulation::Packet message;
  message.kind = vn_emulation::Kind::vn_message;
  message.age = 0;
  message.from = 0;
  vn_emulation::monitor_transmit(slots, s, 0, message);
  const auto refused = vn_emulation::refinement_failure(slots, s);
  REQUIRE(refused);
  CHECK(refused->find("did not send") != std::string::npos);
}

TEST_CASE("vn-emulation no-live-restart: with two fails two joiners' resets restart a live VN "
          "(the specification's F4)",
          "[vn-emulation][slow][long]") {
  CHECK(et::run("no-live-restart", {}).result.verdict == checker::Verdict::holds);
  checker::ExploreOptions bounded;
  bounded.limits.max_states = 4'000'000; // the trace is 41 steps deep; the whole space 20M+
  const et::Run r = et::run("no-live-restart", {"fails=2"}, bounded);
  CHECK(r.result.verdict == checker::Verdict::violated);
  REQUIRE(r.result.trace);
  CHECK(r.result.trace->length() == 41);
  // The trace is cut to the emulation's variables and replays on the model's automaton.
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(r.system), *r.result.trace, &why));
  INFO(why);
}

TEST_CASE("vn-emulation F1: restart and init-action as printed stop time for good",
          "[vn-emulation]") {
  // As printed, a joiner's restart keeps its precondition after the reset is sent, so the
  // reset, due d_p + eps later, is never delivered: a cold start time-locks at 7.
  const et::Run restart =
      et::run("no-timelock", {"restart=printed", "start=cold", "messages=0", "fails=0"});
  CHECK(restart.result.verdict == checker::Verdict::violated);
  CHECK(restart.result.trace_kind == "time-lock");
  REQUIRE(restart.result.trace);
  CHECK(restart.result.trace->steps.back().time == 7);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(restart.system), *restart.result.trace, &why));
  INFO(why);
  // The same instance with the decision D7 lets time pass everywhere.
  CHECK(et::run("no-timelock", {"start=cold", "messages=0", "fails=0"}).result.verdict ==
        checker::Verdict::holds);
  // init-action as printed: once the VN has a send to make, time never passes again.
  const et::Run init = et::run("no-timelock", {"init_action=printed", "fails=0"});
  CHECK(init.result.verdict == checker::Verdict::violated);
  REQUIRE(init.result.trace);
  bool suggested = false;
  for (const auto& step : init.result.trace->steps)
    suggested = suggested || step.action.rfind("init-action", 0) == 0;
  CHECK(suggested);
  CHECK(checker::replay(tioa::SuccessorGenerator(init.system), *init.result.trace, &why));
  INFO(why);
}

TEST_CASE("vn-emulation F3: a VN whose send reports its current value misses d_MMT",
          "[vn-emulation]") {
  // Three client messages, received 2 quanta apart: each makes the pending suggestion
  // stale, so the send task waits 3(d_p + eps) = 6 > 2d_p + 2eps = 4.
  const et::Run report = et::run("theorem-2", {"pns=1", "vn=report", "messages=3", "fails=0"});
  CHECK(report.result.verdict == checker::Verdict::violated);
  CHECK_THAT(report.result.message, Catch::StartsWith("d_MMT exceeds Theorem 2's"));
  CHECK(et::figure(report.result, "d_MMT measured") == "6");
  REQUIRE(report.result.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(report.system), *report.result.trace, &why));
  INFO(why);
  // The FIFO counter, on the same inputs, sends within d_p + eps.
  const auto fifo = et::run("theorem-2", {"pns=1", "messages=3", "fails=0"}).result;
  CHECK(fifo.verdict == checker::Verdict::holds);
  CHECK(et::figure(fifo, "d_MMT measured") == "2");
}

TEST_CASE("vn-emulation theorem-2: VN messages reach the clients within d_p", "[vn-emulation]") {
  for (const auto& [d_p, expected] : {std::pair{1, "1"}, std::pair{2, "2"}}) {
    const auto r = et::run("theorem-2", {"fails=0", "d_p=" + std::to_string(d_p)}).result;
    CHECK(r.verdict == checker::Verdict::holds);
    CHECK(et::figure(r, "d_v VN -> CN measured") == expected);
    CHECK(et::figure(r, "d_v measured") == et::figure(r, "d_v CN -> VN measured"));
  }
}

TEST_CASE("vn-emulation, two zones: the radius condition decides VN -> VN delivery",
          "[vn-emulation]") {
  // One PN per zone, placed anywhere in it, no motion, no failure, one client message.
  // With R_p^2 >= 10 (the far corners of the two zones, the lattice's sqrt(5) b) every
  // figure is met; with 9 a VN's message from one far corner never reaches the other
  // zone's only replica (the cap, 12, is "never while alive"): P9 of the specification.
  const auto near = et::run("theorem-2", {"zones=2", "fails=0", "moves=0", "rp2=10"}).result;
  CHECK(near.verdict == checker::Verdict::holds);
  CHECK(et::figure(near, "d_v VN -> VN measured") == "3");
  CHECK(et::figure(near, "d_v VN -> CN measured") == "1");
  CHECK(et::run("replica-consistency", {"zones=2", "fails=0", "moves=0"}).result.verdict ==
        checker::Verdict::holds);
  const et::Run far = et::run("theorem-2", {"zones=2", "fails=0", "moves=0", "rp2=9"});
  CHECK(far.result.verdict == checker::Verdict::violated);
  CHECK(et::figure(far.result, "d_v VN -> VN measured") == "12");
  CHECK(et::figure(far.result, "d_v CN -> VN measured") == "3");
  REQUIRE(far.result.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(far.system), *far.result.trace, &why));
  INFO(why);
  // P7 with a reference replica per zone: each VN takes its neighbour's report, and the
  // replicas of each zone hold their VN's state.
  CHECK(et::run("refines-vn", {"zones=2", "fails=0", "moves=0"}).result.verdict ==
        checker::Verdict::holds);
}

TEST_CASE("vn-emulation, two zones: a PN that moves across starts again in its new zone",
          "[vn-emulation]") {
  // One move: a PN may step into the other zone, zone-update, join and be acked there.
  const auto r = et::run("theorem-2", {"zones=2", "fails=0", "moves=1"}).result;
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(r.states == 864'072);
  CHECK(et::figure(r, "d_v measured") == "3");
}

TEST_CASE("vn-emulation on the fingerprint store: the same states, what holds is incomplete, "
          "and a violation or a bound met comes with a trace that replays",
          "[vn-emulation]") {
  checker::ExploreOptions fingerprints;
  fingerprints.store = checker::StoreKind::fingerprint;
  const auto agree = et::run("replica-consistency", {}, fingerprints).result;
  CHECK(agree.verdict == checker::Verdict::incomplete);
  CHECK_THAT(agree.message, Catch::StartsWith("holds up to hash collisions"));
  CHECK(agree.states == 120'790); // as on the exact store
  CHECK(agree.omission_probability.value_or(0) > 0);
  CHECK(et::run("refines-vn", {}, fingerprints).result.states == 132'452);

  // R_p = 1 loses packets inside a zone (README, P1): the search stops at the first state
  // where the replicas differ, with the exact store's shortest trace (26 steps), before the
  // exact store's 2,723,388 states.
  const et::Run lossy =
      et::run("replica-consistency", {"zones=2", "fails=0", "moves=1", "rp2=1"}, fingerprints);
  CHECK(lossy.result.verdict == checker::Verdict::violated);
  CHECK_THAT(lossy.result.message,
             Catch::StartsWith("replicas disagree where time passes: the active replicas PN_0 "
                               "and PN_1 hold different VN states"));
  CHECK(lossy.result.states < 2'723'388);
  REQUIRE(lossy.result.trace);
  CHECK(lossy.result.trace->length() == 26);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(lossy.system), *lossy.result.trace, &why));
  INFO(why);

  // A time-lock (F1) is found as on the exact store.
  const et::Run locked = et::run("no-timelock", {"init_action=printed", "fails=0"}, fingerprints);
  CHECK(locked.result.verdict == checker::Verdict::violated);
  REQUIRE(locked.result.trace);
  CHECK(checker::replay(tioa::SuccessorGenerator(locked.system), *locked.result.trace, &why));

  // theorem-2 measures the states as the search meets them: the same worst figures, with a
  // witness of the one nearest its bound; and F3's d_MMT 6 > 4 is found (as a first state
  // past 4: the search stops there).
  const et::Run theorem = et::run("theorem-2", {}, fingerprints);
  CHECK(theorem.result.verdict == checker::Verdict::incomplete);
  CHECK_THAT(theorem.result.message, Catch::StartsWith("holds up to hash collisions"));
  CHECK(et::figure(theorem.result, "d_MMT measured") == "2");
  CHECK(et::figure(theorem.result, "d_v measured") == "3");
  REQUIRE(theorem.result.trace);
  CHECK(theorem.result.trace_kind == "worst-case");
  CHECK(checker::replay(tioa::SuccessorGenerator(theorem.system), *theorem.result.trace, &why));
  const et::Run late =
      et::run("theorem-2", {"pns=1", "messages=3", "fails=0", "vn=report"}, fingerprints);
  CHECK(late.result.verdict == checker::Verdict::violated);
  CHECK_THAT(late.result.message, Catch::StartsWith("d_MMT exceeds Theorem 2's 2d_p + 2eps = 4"));
  REQUIRE(late.result.trace);
  CHECK(late.result.trace->length() == 37); // as on the exact store
  CHECK(checker::replay(tioa::SuccessorGenerator(late.system), *late.result.trace, &why));
}

TEST_CASE("vn-emulation on the fingerprint store: a model bound met is found and traced",
          "[vn-emulation][slow]") {
  checker::ExploreOptions fingerprints;
  fingerprints.store = checker::StoreKind::fingerprint;
  const et::Run r =
      et::run("replica-consistency", {"start=cold", "messages=1", "fails=0"}, fingerprints);
  CHECK(r.result.verdict == checker::Verdict::incomplete);
  CHECK_THAT(r.result.message, Catch::Contains("the bound on TOBcast's buffer"));
  CHECK(r.result.trace_kind == "bound");
  REQUIRE(r.result.trace);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(r.system), *r.result.trace, &why));
  INFO(why);
}

TEST_CASE("vn-emulation with the MC VN (vn=mc): the replicas agree, the abstract VN is "
          "implemented and Theorem 2's figures hold",
          "[vn-emulation]") {
  // One fail, one message (a cn-update): counts pinned.
  const auto replicas = et::run("replica-consistency", {"vn=mc"}).result;
  CHECK(replicas.verdict == checker::Verdict::holds);
  CHECK(replicas.states == 43'138);
  CHECK(et::run("refines-vn", {"vn=mc"}).result.verdict == checker::Verdict::holds);
  // One PN whose CN sends its round's three messages: the VN sends a vn-update and then a
  // target-update, each task within d_MMT, and the target-update reaches the client.
  const auto theorem = et::run("theorem-2", {"vn=mc", "pns=1", "messages=3", "fails=0"}).result;
  CHECK(theorem.verdict == checker::Verdict::holds);
  CHECK(theorem.states == 2'370);
  CHECK(et::figure(theorem, "d_MMT measured") == "2");
  CHECK(et::figure(theorem, "d_v VN -> CN measured") == "1");
}
