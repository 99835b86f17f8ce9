#pragma once
// How far and how a check may go. Zero means "no limit". A limit that is hit ends the
// run with the verdict incomplete, never holds.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace checker {

// The states a whole property may visit, over all its explorations, enumerations and
// searches, and how many they have visited so far (run_property makes one from max_states).
struct StatesBudget {
  std::uint64_t max = 0;
  std::atomic<std::uint64_t> spent{0};
};

struct Limits {
  std::uint64_t max_states = 0;
  double max_seconds = 0;
  std::uint64_t max_memory_bytes = 0;
  // The process's resident memory when the property started (run_property sets it; 0:
  // unknown): what its earlier runs still hold counts against max_memory_bytes too
  // (memory_left, memory_budget.hpp).
  std::uint64_t resident_base = 0;
  // When the time of the whole property (or suite) is up: run_property sets it from
  // max_seconds, so that a property made of several explorations spends max_seconds in
  // all, not in each (issue 17). None: max_seconds bounds each exploration alone.
  std::optional<std::chrono::steady_clock::time_point> deadline;

  // Shared by the runs of one property (issue 17): max_states bounds them together. None:
  // max_states bounds each run alone.
  std::shared_ptr<StatesBudget> states_budget;

  // The state limit of the next run: max_states, or what the property's budget has left if
  // that is less; 0 means no limit, so a run asks states_exhausted() first (a spent budget
  // also gives 0).
  std::uint64_t states_left() const {
    std::uint64_t left = max_states;
    if (states_budget && states_budget->max > 0) {
      const std::uint64_t spent = states_budget->spent.load(std::memory_order_relaxed);
      const std::uint64_t rest = spent >= states_budget->max ? 0 : states_budget->max - spent;
      left = left == 0 ? rest : std::min(left, rest);
    }
    return left;
  }
  bool states_exhausted() const {
    return states_budget && states_budget->max > 0 &&
           states_budget->spent.load(std::memory_order_relaxed) >= states_budget->max;
  }
  // Counts `states` against the property's budget (a run that has finished).
  void spend_states(std::uint64_t states) const {
    if (states_budget)
      states_budget->spent.fetch_add(states, std::memory_order_relaxed);
  }

  // Whether time is up, `elapsed` seconds into an exploration.
  bool out_of_time(double elapsed) const {
    return (max_seconds > 0 && elapsed > max_seconds) ||
           (deadline && std::chrono::steady_clock::now() > *deadline);
  }
};

// How the visited states are held. `exact`: every state in full (state_store.hpp).
// `fingerprint`: a 64-bit fingerprint per state, and the full states of two levels only
// (fingerprint.hpp): far fewer bytes per state for wide states, but two states with one
// fingerprint count as one, so a search that finds nothing is not a proof (incomplete).
// `compressed`: every state exactly, as a one-word key into a tree of the parts states
// share (state_tree.hpp): exact as `exact`, and few bytes per state for wide states, as
// `fingerprint`; slower than both.
enum class StoreKind { exact, fingerprint, compressed };

const char* to_string(StoreKind kind); // "exact", "fingerprint", "compressed"

struct ExploreOptions {
  Limits limits;
  unsigned threads = 1;
  // Partial-order reduction of zero-time steps (zero_time_reduction.hpp) in the checks
  // where it is sound (invariants, deadlocks and time-locks of timed systems).
  bool por = false;
  // With `por`, the stabilisation check of a timed system too (`--por all`;
  // checker/stabilisation.cpp): the same verdicts and worst times on fewer states, but the
  // sets cost more there (the legal set is visible and reads most of a state), so it pays
  // only where the reduction is large (measured in bench/README.md).
  bool por_stabilisation = false;
  StoreKind store = StoreKind::exact;
  bool progress = false; // a progress line on stderr (only when it is a terminal)
  // At the state limit a run finishes its last level for the edge counts and, with several
  // workers, does it again with one so that the states kept are the first in breadth-first
  // order. A run that only needs to learn that there are more states than the limit (a
  // listing that falls back to sampling) stops at the first state past it instead: on a
  // model with thousands of successors per state the last level costs minutes.
  bool stop_at_state_limit = false;
  std::string task; // shown in the progress line
};

// interrupted: a stop was requested from outside (checker/interrupt.hpp).
enum class StopReason { finished, found, state_limit, time_limit, memory_limit, interrupted };

const char* describe(StopReason reason);

} // namespace checker
