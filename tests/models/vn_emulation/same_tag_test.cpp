// E4 (models/vn_emulation/README.md): a PN that fails and recovers within one instant starts
// its TOBcast sequence numbers again (002:35), so two of its messages can carry the same
// tag ⟨ts, i, seq⟩. TOBcast orders a timestamp's messages by sender and sequence number
// (002:348), which does not order these two; each PN's buffer keeps them in the order they
// arrived, and LBcast may bring them to two PNs in two orders. The test drives the
// emulation along that schedule, step by step (each step must be enabled), and then along
// the first step the generator offers: the two replicas that received the copies in
// different orders execute the two client messages in different orders. A breadth-first
// search of the instance (three PNs, two messages, one fail) runs out of memory long
// before that depth, so the schedule is written out here.
#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

#include "checker/trace.hpp"
#include "models/vn_emulation/emulation.hpp"
#include "models/vn_emulation/predicates.hpp"
#include "tioa/successors.hpp"

namespace {

// The schedule: CN_1's message m0 and CN_2's m1 both reach the VN through PN_0, once
// before its fail and once after, with the same tag ⟨0, 0, 0⟩; PN_1 receives the two
// copies in one order, PN_2 in the other.
const std::vector<std::string> schedule = {
    "cn-send_1",         // CN_1's message m0 (LBcast from PN_1, slot 0)
    "lb-rcv_0(1,0)",     // PN_0 suggests receive(m0)
    "TOBcast_0",         // A = ⟨0, 0, 0⟩: PN_0's first message at time 0
    "lb-rcv_1(0,0)",     // PN_1 holds A
    "fail_0",            // PN_0 restarts from its initial values, sequence 0 (002:35)
    "recover_0",         //
    "zone-update_0",     // h = 0 again (idle: not a replica)
    "cn-send_2",         // CN_2's message m1
    "lb-rcv_0(2,0)",     // PN_0 suggests receive(m1), with no status guard (002:414)
    "TOBcast_0",         // B = ⟨0, 0, 0⟩ again: the same tag as A
    "lb-rcv_2(0,1)",     // PN_2 holds B ...
    "lb-rcv_2(0,0)",     // ... then A
    "lb-rcv_1(0,0)",     // PN_1 holds A, then B
    "join_0",            // PN_0 joins again: its join-req, ⟨0, 0, 1⟩
    "TOBcast_0",         //
    "lb-rcv_0(0,0)",     // B comes back to PN_0
    "lb-rcv_0(0,0)",     // and the join-req goes to every PN
    "lb-rcv_1(0,0)",     //
    "lb-rcv_2(0,0)",     //
    "tick",              // PN_1 and PN_2 take m0 and m1 within d_p, at 1, so that their own
    "lb-rcv_1(1,0)",     // suggestions (stamped 1) are not in TOBcast's buffer beside A and B
    "lb-rcv_2(1,0)",     // (the model's bound is 6 entries)
    "lb-rcv_1(2,0)",     //
    "lb-rcv_2(2,0)",     //
    "TOBcast_1",         //
    "TOBcast_1",         //
    "TOBcast_2",         //
    "TOBcast_2",         //
    "tick",              // at 2 = 0 + d_p + eps TOBcast delivers A and B: PN_1 in the order
    "TOBcast-rcv_1",     // A, B (m0 then m1), PN_2 in the order B, A; each replica executes
    "TOBcast-rcv_1",     // both before it suggests its VN's send (one suggestion each, so that
    "TOBcast-rcv_1",     // TOBcast's buffers keep within their bound)
    "simulate-action_1", //
    "simulate-action_1", //
    "TOBcast-rcv_2",     //
    "TOBcast-rcv_2",     //
    "TOBcast-rcv_2",     //
    "simulate-action_2", //
    "simulate-action_2", //
};

struct Walk {
  checker::Trace trace;
  std::optional<std::string> failure; // replica_failure's, where it first holds
  // Where time may pass after PN_1 and PN_2 have both executed m0 and m1 (and no model
  // bound is met): the states the replicas are compared in.
  int compared = 0;
};

// The schedule from the start state (each step must be enabled), then the first step the
// generator offers, until the replicas disagree, time reaches `until` or a model bound is
// met (TOBcast's buffer, by the VN's sends after 2).
Walk walk(const vn_emulation::Emulation& e, std::uint64_t until) {
  const tioa::Automaton& a = e.automaton;
  const tioa::SuccessorGenerator generator(a);
  std::vector<tioa::Word> words(a.words() + 1, 0), start;
  a.start().enumerate(words.data(), 0, [&] {
    if (start.empty())
      start.assign(words.begin(), words.end() - 1);
  });
  Walk w;
  w.trace.steps.push_back({"", 0, start, {}});
  std::vector<tioa::Word> scratch(a.words() + 1, 0);
  const vn_emulation::Slots& slots = *e.slots;
  for (std::size_t k = 0; !w.failure && w.trace.steps.back().time < until; ++k) {
    const checker::TraceStep& last = w.trace.steps.back();
    const bool scheduled = k < schedule.size();
    std::vector<tioa::Word> next;
    tioa::StepLabel taken;
    generator.successors(
        last.state.data(), scratch.data(), [&](const tioa::Word* s, const tioa::StepLabel& l) {
          if (next.empty() && (!scheduled || generator.describe(l) == schedule[k])) {
            next.assign(s, s + a.words());
            taken = l;
          }
        });
    INFO("step " << k + 1 << (scheduled ? ": " + schedule[k] : std::string()));
    REQUIRE_FALSE(next.empty());
    w.trace.steps.push_back({generator.describe(taken), last.time + generator.duration(taken), next,
                             checker::trace_action(generator, taken)});
    const tioa::State reached(w.trace.steps.back().state.data(), 0);
    if (slots.past_bound(reached))
      break;
    w.failure = vn_emulation::replica_failure(slots, reached);
    if (!vn_emulation::urgent(slots, reached) && slots.completed(reached, 1).received == 3 &&
        slots.completed(reached, 2).received == 3)
      ++w.compared;
  }
  return w;
}

vn_emulation::EmuConfig e4_instance(vn_emulation::Ties ties) {
  vn_emulation::EmuConfig c;
  c.pns = 3;
  c.messages = 2;
  c.fails = 1;
  c.ties = ties;
  return c;
}

} // namespace

TEST_CASE("vn-emulation E4: two messages with one TOBcast tag reach two replicas in two orders",
          "[vn-emulation]") {
  const vn_emulation::Emulation e =
      vn_emulation::emulation(e4_instance(vn_emulation::Ties::arrival));
  const Walk w = walk(e, 4);
  REQUIRE(w.failure);
  CHECK(*w.failure ==
        "the active replicas PN_1 and PN_2 hold different VN states where time passes: (count 0, "
        "last CN_2, out [<1, CN_1>, <0, CN_2>], sseq 0) and (count 0, last CN_1, out [<1, CN_2>, "
        "<0, CN_1>], sseq 0)");
  CHECK(w.trace.steps.back().time == 2);
  CHECK(w.trace.length() == 62);
  std::string why;
  CHECK(checker::replay(tioa::SuccessorGenerator(e.automaton), w.trace, &why));
  INFO(why);
}

TEST_CASE("vn-emulation E4 repaired: with ties by content the replicas agree on that schedule",
          "[vn-emulation]") {
  const vn_emulation::Emulation e =
      vn_emulation::emulation(e4_instance(vn_emulation::Ties::content));
  const Walk w = walk(e, 4);
  CHECK_FALSE(w.failure);
  CHECK(w.compared > 0);
}
