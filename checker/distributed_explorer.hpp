#pragma once
// Breadth-first exploration over the ranks of a distributed run (issue 18), level by
// level. Each rank owns the states whose hash maps to it (owner_of()), keeps them in a
// store of its own, expands the ones of the frontier it owns and sends each successor, in
// batches, to its owner; a level ends when every rank has expanded its share (the
// exchange is collective, so the ranks stay in step and need no termination detection).
//
// The same ids as one process: a state's id is the one a sequential search gives it. A
// new state keeps its smallest discovery key (the id of the state it was found from, the
// index of the step), as discovery.hpp does for threads; at the end of a level every rank
// learns every rank's sorted keys (8 bytes per new state of the level, on every rank) and
// numbers its own states by their place among them. So the counts, the first target
// found (smallest id), the depth and the trace (rebuilt across ranks by asking the owner
// of each parent in turn) are those of one process.
//
// Within a rank, options.threads threads expand the round's frontier states (each into its
// own messages) and insert what the rank receives (the store's concurrent insertion, each
// new state's key kept with an atomic minimum); the ids do not depend on who inserts first.
// A rank holds per state, beside its store, 12 bytes (the state's id, its parent's id and
// its place in id order) and, while a level is built, 8 bytes of key per new state.
//
// With a reduction (zero_time_reduction.hpp), a rank expands a state as one process does:
// the reduction's choice depends on the state alone, so the reduced graph, its counts and
// its ids are one process's too.
//
// A rank's error while it inserts start states, expands or inserts is caught there; the
// rank goes on with the exchanges, and at the next look at the limits every rank learns
// of it: out of memory (or a full store) stops them all as at the memory limit, with a
// note naming the rank (`failure`); a model's error is thrown on every rank, as one
// process throws it. No rank is left waiting for one that stopped.
//
// On the fingerprint store a rank's store holds fingerprints, the owner of a state is that
// of its fingerprint (so two states that share one meet, and count as one, as in one
// process), and the trace is rebuilt by re-execution from the owners' fingerprints. The
// full states of the frontier and of the level being built are kept, as one process
// keeps them.
//
// On the compressed store each rank has its own tree of parts (state_tree.hpp): the owner
// of a state is that of the state itself, as on the exact store, and the owner makes its
// key when it inserts it (a state whose parts find a table full waits until the threads
// are done and the tables have grown); a state of the frontier and of a trace is decoded
// from its key.
//
// Not yet: recorded edges, and the checks built on them.

#include <optional>
#include <string>
#include <vector>

#include "checker/collective.hpp"
#include "checker/exploration.hpp"
#include "checker/options.hpp"
#include "checker/zero_time_reduction.hpp"
#include "tioa/start_set.hpp"
#include "tioa/successors.hpp"

namespace checker {

struct DistributedExploration {
  std::uint64_t states = 0; // on every rank: the whole run's
  std::uint64_t start_states = 0;
  std::uint64_t edges = 0;
  std::uint64_t reduced_states = 0; // expanded in part by the reduction
  std::uint32_t depth = 0;
  StopReason stop = StopReason::finished;
  std::optional<std::uint64_t> found;      // the id of the first target
  std::vector<std::vector<Word>> to_found; // the states from a start state to it
  // Expanded states with no successor: those `ended` calls proper ends, and the others
  // (stuck), with the first of them (smallest id) and the states to it.
  std::uint64_t ended = 0, stuck = 0;
  std::optional<std::uint64_t> first_stuck;
  std::vector<std::vector<Word>> to_first_stuck;
  double seconds = 0;
  std::uint32_t threads = 1; // threads in each rank
  bool fingerprints = false; // on the fingerprint store (fingerprint.hpp)
  bool compressed = false;   // on the compressed store (state_tree.hpp)
  // The compressed store: the parts the ranks' trees hold, and the bytes of their stores
  // and trees, summed over the ranks.
  std::uint64_t parts = 0;
  std::uint64_t store_bytes = 0;
  std::string failure; // a rank out of memory stopped the run (stop: memory_limit): which, why
  std::size_t peak_rank_bytes = 0; // the largest resident memory of a rank
  bool complete() const { return stop == StopReason::finished || stop == StopReason::found; }
};

// `target` (may be empty): the states to look for; the search stops at the level of the
// first. `ended` (may be empty): the states with no successor that are proper ends.
// `reduction` (may be null): the partial-order reduction to expand states with.
// Every rank calls it with the same arguments and gets the same result.
DistributedExploration explore_distributed(const tioa::SuccessorGenerator& generator,
                                           const tioa::StartSet& start,
                                           const ExploreOptions& options,
                                           const tioa::StatePredicate& target,
                                           const tioa::StatePredicate& ended,
                                           const ZeroTimeReduction* reduction, Collective& ranks);

// The rank that owns a state of this hash (state_hash.hpp), among `ranks`: from a mix of
// the hash of its own, so that the states of a rank still spread over its whole table.
int owner_of(std::uint64_t hash, int ranks);

} // namespace checker
