// A heartbeat failure detector written against the installed tioa library, the way code
// outside this repository uses it. docs/examples.md walks through it line by line.
//
//   sender    output beat         clock since (0..P)   deadline: a beat is due at since = P
//   receiver  input beat          clock heard (0..T+1) alive while it heard a beat within T
//             output suspect      urgent once heard > T
//
// System: Fail(sender) || receiver; the environment drives fail_sender and restart_sender.
// The program runs four checks and exits 0 only if each gives the expected verdict.

#include <cstdint>
#include <iomanip>
#include <iostream>
#include <string>

#include "checker/checks.hpp"
#include "checker/trace.hpp"
#include "tioa/tioa.hpp"

using checker::PropertyResult;
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

// The system, with and without an arbitrary start for the sender, and its two properties.
struct Heartbeat {
  Automaton system;   // Fail(sender) || receiver, from their start states
  Automaton anywhere; // U(Fail(sender)) || receiver: the sender starts in any state
  tioa::StatePredicate no_false_suspicion = {}, consistent = {};
};

Heartbeat build(int period, int timeout) {
  // §3.2: Fail adds the variable `failed` and the inputs fail_sender, restart_sender.
  const Automaton failing = tioa::Fail(sender(period));
  // §3.1 composition (beat: the sender's output drives the receiver's input); §3.3 U.
  Heartbeat h{.system = tioa::compose("heartbeat", {failing, receiver(timeout)}),
              .anywhere = tioa::compose("heartbeat", {tioa::U(failing), receiver(timeout)})};
  const auto since = tioa::find_variable<int>(h.system, "sender.since");
  const auto heard = tioa::find_variable<int>(h.system, "receiver.heard");
  const auto failed = tioa::find_variable<bool>(h.system, "sender.failed");
  const auto alive = tioa::find_variable<bool>(h.system, "receiver.alive");
  // The receiver suspects only a sender that failed, or restarted after the last beat it
  // heard (then heard > since).
  h.no_false_suspicion = [=](const State& s) {
    return s[alive] || s[failed] || s[heard] > s[since];
  };
  // L: the receiver's belief is consistent with the sender: it heard no beat the sender did
  // not send (heard >= since) and suspects only after more than T quanta of silence.
  // "alive exactly when the sender is up" is no legal set: the environment may fail the
  // sender at any time and the receiver learns it only T quanta later, so that set is not
  // closed under fail_sender (§3.1). L must allow a failed sender that is still trusted.
  h.consistent = [=](const State& s) {
    return s[heard] >= s[since] && (s[alive] || s[heard] > timeout);
  };
  return h;
}

// Prints a trace, one state a line; false if it does not replay against the model.
bool print_trace(const Automaton& system, const checker::Trace& trace) {
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const checker::TraceStep& step = trace.steps[i];
    std::cout << "    t=" << step.time << "  " << std::left << std::setw(16)
              << (step.action.empty() ? "(start)" : step.action);
    for (const auto& [name, value] : checker::render_state(system.layout(), step.state.data()))
      std::cout << "  " << name << "=" << value;
    std::cout << (trace.loop_start == i ? "  <- loop starts" : "") << "\n";
  }
  std::string why;
  const bool replays = checker::replay(tioa::SuccessorGenerator(system), trace, &why);
  if (!replays)
    std::cout << "    the trace does not replay: " << why << "\n";
  return replays;
}

// Prints one verdict; true when it is the expected one.
bool report(const std::string& title, const Automaton& system, const PropertyResult& r,
            Verdict expected) {
  bool ok = r.verdict == expected;
  std::cout << "\n"
            << title << "\n  verdict: " << checker::to_string(r.verdict) << " (expected "
            << checker::to_string(expected) << ")" << (ok ? "" : "  <-- UNEXPECTED") << "\n  "
            << r.message << "\n  explored " << r.states << " states, " << r.edges << " edges\n";
  for (const std::string& note : r.notes)
    std::cout << "  note: " << note << "\n";
  if (r.trace) {
    std::cout << "  " << r.trace_role << " (" << r.trace_kind << "):\n";
    ok &= print_trace(system, *r.trace);
  }
  return ok;
}

} // namespace

int main() try {
  constexpr int period = 3, timeout = 3, short_timeout = 2; // in quanta
  const checker::ExploreOptions options;
  const Heartbeat good = build(period, timeout), hasty = build(period, short_timeout);
  std::cout << "heartbeat: P = " << period << ", T = " << timeout
            << " (one quantum = 1 time unit)\n";

  bool ok = report("(a) invariant: no false suspicion, T = P", good.system,
                   checker::check_invariant(good.system, good.no_false_suspicion, options),
                   Verdict::holds);
  ok &= report("(b) legal set (§3.1): consistent belief is closed", good.system,
               checker::check_legal_set(good.system, good.consistent, options), Verdict::holds);
  // Def 3.5: Fail(sender) self-stabilises to L relative to the receiver, even though the
  // environment may keep failing and restarting the sender.
  const PropertyResult stab = checker::check_stabilisation(good.anywhere, good.consistent, options);
  ok &= report("(c) stabilisation (Def 3.5): U(Fail(sender)) || receiver -> consistent belief",
               good.anywhere, stab, Verdict::holds);
  if (stab.worst_time) {
    std::cout << "  worst-case stabilisation time: " << *stab.worst_time << " " << stab.time_unit
              << " (expected " << period << ")\n";
    ok &= *stab.worst_time == static_cast<std::uint64_t>(period);
  }
  ok &= report("(d) invariant: no false suspicion, T = " + std::to_string(short_timeout) + " < P",
               hasty.system,
               checker::check_invariant(hasty.system, hasty.no_false_suspicion, options),
               Verdict::violated);

  std::cout << "\n" << (ok ? "all verdicts as expected" : "UNEXPECTED VERDICT") << "\n";
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::cerr << "heartbeat: " << e.what() << "\n";
  return 2;
}
