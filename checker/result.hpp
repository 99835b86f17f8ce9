#pragma once
// The outcome of one property check: a verdict, the figures the run measured, and a
// trace (a counterexample, or a witness of the worst case).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checker/trace.hpp"
#include "tioa/automaton.hpp"

namespace checker {

enum class Verdict { holds, violated, incomplete };

const char* to_string(Verdict verdict);

// How the start states a property's statement quantifies over were chosen: every one of
// them, a part of them (a seeded draw, a family built by a rule), or a single one.
enum class Starts { all, sampled, one };

const char* to_string(Starts starts); // "all", "sampled", "one"

// What a run covered of what its statement quantifies over (issue 15). A verdict of holds
// claims exactly this: run_property() turns holds into incomplete unless starts is all.
struct Coverage {
  Starts starts = Starts::all;
  std::uint64_t count = 0;         // start states (or pairs, or instances) covered
  std::optional<std::uint64_t> of; // out of how many, when known
  std::string over;                // what the statement quantifies over, in words
  std::string chosen;              // how the covered ones were chosen, when not all
};

struct PropertyResult {
  std::string name;
  std::string kind; // invariant, legal-set, stabilisation, transitivity, deadlock
  std::string description;
  Verdict verdict = Verdict::incomplete;
  std::string message; // one line: why this verdict

  std::uint64_t states = 0;
  std::uint64_t edges = 0;
  std::uint32_t depth = 0;
  double seconds = 0;
  unsigned threads = 1;
  unsigned ranks = 1;               // processes of a distributed run (distributed_explorer.hpp)
  bool por = false;                 // zero-time steps were reduced: counts are the reduced graph's
  std::uint64_t reduced_states = 0; // states expanded with fewer steps than were enabled
  std::string store = "exact";      // how the visited states were held: "exact" or "fingerprint"
  // The fingerprint store only: the probability that a state was missed (fingerprint.hpp).
  std::optional<double> omission_probability;

  Coverage coverage;

  std::string time_unit; // "steps" or "quanta"
  std::optional<std::uint64_t> worst_time;
  std::optional<std::uint64_t> last_time_outside;

  std::optional<Trace> trace;
  // The automaton whose states and steps the trace is made of, when the check explored
  // another one than the model's system (vlayer-mc's arbitrary start states have junk
  // slots, D31); null: the system. Reports render the trace with trace_layout_or().
  std::shared_ptr<const tioa::Automaton> trace_system;
  // The name its model gives that automaton (catalogue::ModelInstance::trace_systems), which
  // a trace file records so that `replay` can replay the trace on it.
  std::string trace_system_name;
  const tioa::StateLayout& trace_layout_or(const tioa::StateLayout& system) const {
    return trace_system ? trace_system->layout() : system;
  }
  std::string trace_role; // "counterexample" or "witness"
  std::string trace_kind; // invariant, lasso, deadlock, time-lock, closure-step, worst-case
  // For a property with a legal set L (stabilisation, transitivity: L2, legal-set): its
  // name, and whether each state of the trace is in it (run_property fills them).
  std::string legal_set_name;
  std::vector<bool> trace_in_legal_set;
  std::vector<std::string> notes;
  std::vector<std::pair<std::string, std::string>> figures; // further named numbers
  // Counterexamples and witnesses that are not traces of the automaton (a round of
  // mc-round's lemmas, a matrix of Lemma 6.8): each one JSON object as text, {"role",
  // "kind", "claim", ...} (proofs/witness_json.hpp), for --json and --trace-out.
  std::vector<std::string> witnesses;
};

// A result of `kind` with the figures of an exploration: states, edges, depth, seconds,
// threads, the store (and on the fingerprint store the omission probability), and the unit
// of time of the generator ("quanta" timed, "steps" untimed).
PropertyResult result_of(const std::string& kind, const Exploration& ex,
                         const tioa::SuccessorGenerator& generator);

// An input of the system that no component outputs (tioa/compose.cpp keeps the points no
// output covers) is tried at every point of its box in every state. Adds a note for each
// with at least `open_input_points` points and no parameter bound to the state.
inline constexpr double open_input_points = 1e4;
void note_open_inputs(const tioa::Automaton& automaton, PropertyResult& result);

// "N reachable states", or, when zero-time steps were reduced, "the N reachable states of
// the reduced graph": a reduced search visits only some of the reachable states.
std::string reachable_states(std::uint64_t count, const Exploration& ex);
// The message of an invariant broken, with the length of its trace (`reduced_states`:
// the states the reduction expanded in part, 0 for none).
std::string invariant_broken(std::size_t trace_length, std::uint64_t reduced_states);
// The same from how many states the reduction expanded in part (0: none).
std::string reachable_states(std::uint64_t count, std::uint64_t reduced_states);

// "all, 4 of 4: the start states", "sampled, 1000 of 5120000: U(VLNodes) x R(env) (drawn
// at random, seed 1)".
std::string describe(const Coverage& coverage);

// A run that covered less than its statement asks (coverage.starts is not all) does not
// hold: its holds becomes incomplete, the message saying on how many start states it held.
void claim_only_covered(PropertyResult& result);

// Sets verdict and message for a run that stopped on a limit.
void mark_incomplete(PropertyResult& result, const Exploration& ex, const std::string& covered);

// Sets verdict and message for a run that finished and found no violation: holds, with
// `message`; on the fingerprint store incomplete, "holds up to hash collisions, omission
// probability ≤ p: " and `message` (a state may have been missed).
void mark_holds(PropertyResult& result, const Exploration& ex, const std::string& message);

// The omission probability as the reports print it ("3.3e-06").
std::string format_probability(double p);

} // namespace checker
