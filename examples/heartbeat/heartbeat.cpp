// A heartbeat failure detector written against the installed tioa package, the way code
// outside this repository uses it: the automata and their properties, registered as one
// model, and the command line of tioa-check around them (list, check, explore, walk, replay, suite,
// sweep; text, JSON, JUnit and HTML reports) from cli::run. docs/examples.md walks through it.
//
//   sender    output beat         clock since (0..P)   deadline: a beat is due at since = P
//   receiver  input beat          clock heard (0..T+1) alive while it heard a beat within T
//             output suspect      urgent once heard > T
//
// System: Fail(sender) || receiver; the environment drives fail_sender and restart_sender.

#include <optional>
#include <string>

#include "catalogue/registry.hpp"
#include "checker/checks.hpp"
#include "cli/app.hpp"
#include "tioa/tioa.hpp"

using catalogue::ModelDefinition;
using catalogue::ModelInstance;
using catalogue::ParamValues;
using checker::PropertyKind;
using checker::Verdict;
using tioa::Automaton;
using tioa::Params;
using tioa::State;

namespace {

// The sender beats at most every P quanta: time cannot pass once `since` reaches P.
Automaton sender(int period) {
  Automaton a("sender");
  const auto since = a.clock("since", period, 0); // quanta since the last beat
  a.output("beat")
      .pre([=](const State& s, const Params&) { return s[since] >= 1; })
      .eff([=](State& s, const Params&) { s[since] = 0; });
  a.trajectories([=](State& s) { s.advance(since); },                 // evolve
                 [=](const State& s) { return s[since] == period; }); // stop-when
  return a;
}

// The receiver trusts the sender while it heard a beat within T quanta.
Automaton receiver(int timeout) {
  Automaton a("receiver");
  const auto heard = a.clock("heard", timeout + 1, 0); // saturates: T+1 reads "more than T"
  const auto alive = a.boolean("alive", true);
  a.input("beat").eff([=](State& s, const Params&) {
    s[heard] = 0;
    s[alive] = true;
  });
  const auto expired = [=](const State& s) { return s[alive] && s[heard] > timeout; };
  a.output("suspect")
      .pre([=](const State& s, const Params&) { return expired(s); })
      .eff([=](State& s, const Params&) { s[alive] = false; });
  a.trajectories([=](State& s) { s.advance(heard); }, expired); // suspect is urgent
  return a;
}

// One instance: the system from its start states, and its three properties.
ModelInstance build(int period, int timeout) {
  // §3.2: Fail adds the variable `failed` and the inputs fail_sender, restart_sender.
  const Automaton failing = tioa::Fail(sender(period));
  // §3.1 composition (beat: the sender's output drives the receiver's input); §3.3 U: the
  // same system with the sender started in any state, for Def 3.5.
  const Automaton system = tioa::compose("heartbeat", {failing, receiver(timeout)});
  const Automaton anywhere = tioa::compose("heartbeat", {tioa::U(failing), receiver(timeout)});

  const auto since = tioa::find_variable<int>(system, "sender.since");
  const auto heard = tioa::find_variable<int>(system, "receiver.heard");
  const auto failed = tioa::find_variable<bool>(system, "sender.failed");
  const auto alive = tioa::find_variable<bool>(system, "receiver.alive");
  // The receiver suspects only a sender that failed, or restarted after the last beat it
  // heard (then heard > since).
  const tioa::StatePredicate no_false_suspicion = [=](const State& s) {
    return s[alive] || s[failed] || s[heard] > s[since];
  };
  // L: the receiver heard no beat the sender did not send (heard >= since) and suspects
  // only after more than T quanta of silence. ("Alive exactly when the sender is up" is no
  // legal set: the environment may fail the sender at any time, §3.1.)
  const tioa::StatePredicate consistent = [=](const State& s) {
    return s[heard] >= s[since] && (s[alive] || s[heard] > timeout);
  };

  ModelInstance m{system, {}, "1 time unit"};
  m.properties = {
      {"no-false-suspicion",
       "invariant: the receiver suspects only a failed or restarted sender",
       PropertyKind::invariant,
       no_false_suspicion,
       "no false suspicion",
       {},
       ""},
      {"consistent-closed",
       "L = consistent belief is closed under every step (§3.1)",
       PropertyKind::legal_set,
       consistent,
       "consistent belief",
       {},
       ""},
      {"stabilisation",
       "U(Fail(sender)) || receiver stabilises to L = consistent belief "
       "(Def 3.5)",
       PropertyKind::custom,
       {},
       "",
       {},
       "",
       [=](const checker::ExploreOptions& options) {
         return checker::check_stabilisation(anywhere, consistent, options);
       }},
  };
  return m;
}

ModelDefinition heartbeat_definition() {
  ModelDefinition d;
  d.name = "heartbeat";
  d.description = "a heartbeat failure detector: Fail(sender) || receiver (time: quanta)";
  d.params = {{"P", 3, 1, 10, "the sender's period: a beat at least every P quanta"},
              {"T", 3, 1, 10, "the receiver's timeout: it suspects after more than T quanta"}};
  d.properties = {{"no-false-suspicion", "the receiver suspects only a failed or restarted sender"},
                  {"consistent-closed", "L = consistent belief is a legal set (closure)"},
                  {"stabilisation", "U(Fail(sender)) || receiver stabilises to L; worst time"}};
  d.build = [](const ParamValues& p) {
    return build(static_cast<int>(p.at("P").integer()), static_cast<int>(p.at("T").integer()));
  };
  d.suite = {{{}, "no-false-suspicion", Verdict::holds},
             {{}, "consistent-closed", Verdict::holds},
             {{}, "stabilisation", Verdict::holds},
             {{{"T", 2}}, "no-false-suspicion", Verdict::violated}};
  return d;
}

} // namespace

int main(int argc, char** argv) {
  catalogue::Catalogue models;
  models.add(heartbeat_definition());
  return cli::run(argc, argv, models);
}
