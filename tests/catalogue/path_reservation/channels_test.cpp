// The readings of seed 004 that issue 16 added: the order of the channels (§2: "reliable
// but non FIFO"), their capacity, the reach of Discover and of delivery, and the repaired
// protocol with round tags (models/path_reservation/README.md, "The table of readings").
#include <catch2/catch.hpp>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "models/path_reservation/network.hpp"
#include "tests/catalogue/path_reservation/run_check.hpp"
#include "tioa/automaton.hpp"

using checker::Verdict;
using path_reservation::ChannelOrder;
using path_reservation::Message;
using path_reservation::MessageKind;
using path_reservation::Network;
using path_reservation_test::run;

namespace {

Message message(MessageKind kind, int round) {
  Message m;
  m.kind = kind;
  m.round = round;
  return m;
}

struct Channels {
  tioa::Automaton a{"channels"};
  Network net;
  std::vector<tioa::Word> words;
  Channels(int capacity, ChannelOrder order)
      : net(a, 2, capacity, order, false), words(a.words() + 1, 0) {
    tioa::State s(words.data(), 0);
    for (const auto& info : a.layout().variables())
      s.set_code(info.slot(), info.initial_code.value_or(0));
  }
  tioa::State state() { return tioa::State(words.data(), 0); }
};

} // namespace

TEST_CASE("path-reservation: a multiset channel holds one content as one state",
          "[path-reservation][channels]") {
  Channels one(3, ChannelOrder::any), other(3, ChannelOrder::any);
  auto s = one.state();
  auto t = other.state();
  one.net.send(s, 1, 2, message(MessageKind::release, 1));
  one.net.send(s, 1, 2, message(MessageKind::request, 2));
  other.net.send(t, 1, 2, message(MessageKind::request, 2));
  other.net.send(t, 1, 2, message(MessageKind::release, 1));
  CHECK(one.words == other.words);
  // Every message may go first; equal messages are one choice.
  const auto all = path_reservation::kind_bit(MessageKind::request) |
                   path_reservation::kind_bit(MessageKind::release);
  CHECK(one.net.deliverable(s, 1, 2, MessageKind::release, all) == 1);
  CHECK(one.net.deliverable(s, 1, 2, MessageKind::request, all) == 1);
  one.net.send(s, 1, 2, message(MessageKind::request, 2));
  CHECK(one.net.deliverable(s, 1, 2, MessageKind::request, all) == 1);
  // A fourth message does not fit: the state is marked, the channel kept.
  CHECK_FALSE(one.net.overflowed(s));
  one.net.send(s, 1, 2, message(MessageKind::ok, 0));
  CHECK(one.net.overflowed(s));
  CHECK(one.net.kind(s, 1, 2, 1) == MessageKind::request); // sorted: both requests first
  CHECK(one.net.kind(s, 1, 2, 2) == MessageKind::release);
  // Taking a message keeps the rest in order, the empty slots last.
  const Message taken = one.net.take(s, 1, 2, 0);
  CHECK(taken.kind == MessageKind::request);
  CHECK(one.net.kind(s, 1, 2, 2) == MessageKind::none);
}

TEST_CASE("path-reservation: a FIFO channel delivers the first message its receiver reads",
          "[path-reservation][channels]") {
  Channels c(3, ChannelOrder::fifo);
  auto s = c.state();
  c.net.send(s, 1, 2, message(MessageKind::request, 0));
  c.net.send(s, 1, 2, message(MessageKind::release, 0));
  c.net.send(s, 1, 2, message(MessageKind::request, 1));
  const auto requests = path_reservation::kind_bit(MessageKind::request);
  const auto releases = path_reservation::kind_bit(MessageKind::release);
  CHECK(c.net.deliverable(s, 1, 2, MessageKind::request, requests | releases) == 1);
  CHECK(c.net.deliverable(s, 1, 2, MessageKind::release, requests | releases) == 0);
  CHECK(c.net.deliverable_slot(s, 1, 2, MessageKind::request, requests, 0) == 0);
  // A receiver that does not read requests yet takes the release behind the first one.
  CHECK(c.net.deliverable(s, 1, 2, MessageKind::release, releases) == 1);
  c.net.take(s, 1, 2, 0);
  CHECK(c.net.read(s, 1, 2, 1).round == 1);
}

TEST_CASE("path-reservation: findings P1 and P2 under FIFO channels",
          "[path-reservation][channels]") {
  // The literal rule of Alg. 1 line 5 (any request of R_j is msg_j) needs non-FIFO
  // channels to deadlock; the default rule deadlocks under FIFO too.
  for (const char* scenario : {"head-on", "late-joiner", "crossing", "convoy"}) {
    INFO(scenario);
    CHECK(run(scenario, "progress", {"channels=fifo", "msg_rule=any-zone"}).verdict ==
          Verdict::holds);
  }
  CHECK(run("head-on", "progress", {"msg_rule=any-zone"}).verdict == Verdict::violated);
  CHECK(run("head-on", "progress", {"channels=fifo"}).verdict == Verdict::violated);
  CHECK(run("late-joiner", "progress", {"channels=fifo"}).verdict == Verdict::violated);
}

TEST_CASE("path-reservation: round tags repair P1 and P2 in any order",
          "[path-reservation][channels]") {
  for (const char* rule : {"msg_rule=discover-zone", "msg_rule=any-zone"})
    for (const char* channels : {"channels=any", "channels=fifo"})
      for (const char* scenario : {"crossing", "head-on", "convoy", "cycle", "late-joiner"}) {
        INFO(rule << " " << channels << " " << scenario);
        for (const char* property : {"mutual-exclusion", "integrity", "no-collision", "progress"})
          CHECK(run(scenario, property, {"variant=round-tags", rule, channels}).verdict ==
                Verdict::holds);
      }
}

TEST_CASE("path-reservation: a full channel makes a check incomplete, never a wrong verdict",
          "[path-reservation][channels]") {
  // convoy holds with room for four messages a pair; with one, a second message to R1
  // does not fit after 9 steps.
  const auto r = run("convoy", "progress", {"capacity=1"});
  REQUIRE(r.verdict == Verdict::incomplete);
  REQUIRE(r.trace);
  CHECK(r.trace_kind == "bound");
  CHECK(r.trace->length() == 9);
  CHECK_FALSE(r.worst_time);
  const auto& definition = catalogue::builtin_models().find("path-reservation");
  const auto instance =
      definition.build(catalogue::resolve_params(definition, {"scenario=convoy", "capacity=1"}));
  REQUIRE(instance.beyond_bound);
  CHECK(instance.beyond_bound(tioa::State(r.trace->steps.back().state.data(), 0)));
  // A violation that needs no full channel is still found, with the bound in a note.
  const auto late = run("late-joiner", "progress", {"capacity=1"});
  CHECK(late.verdict == Verdict::violated);
  REQUIRE(late.trace);
  CHECK_FALSE(instance.beyond_bound(tioa::State(late.trace->steps.back().state.data(), 0)));
  CHECK(run("convoy", "no-collision", {"capacity=1"}).verdict == Verdict::incomplete);
  CHECK(run("convoy", "no-collision", {"capacity=2"}).verdict == Verdict::holds);
}

TEST_CASE("path-reservation: a closed reach lets the robots of range-edge hear each other",
          "[path-reservation][channels]") {
  for (const char* property : {"mutual-exclusion", "integrity", "no-collision", "progress"}) {
    INFO(property);
    CHECK(run("range-edge", property, {"reach=closed"}).verdict == Verdict::holds);
  }
  CHECK(run("range-edge", "no-collision").verdict == Verdict::violated);
}
