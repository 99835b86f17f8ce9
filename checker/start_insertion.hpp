#pragma once
// Start insertion (level 0): the start set is enumerated, each state replaced by its
// representative (the canonical hook), and the states inserted in batches whose slots in
// the store are prefetched first, so that their cache misses overlap.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "checker/exploration.hpp"
#include "checker/hooks.hpp"
#include "checker/insertion.hpp"
#include "tioa/start_set.hpp"

namespace checker {

inline constexpr std::size_t start_batch = 256;

// Inserts the start states, in enumeration order (they are level 0: ids 0.. size() - 1).
// `after_batch(stopped)` runs after each batch (the run's time and memory checks, the progress
// line) and returns why the run stops, if it does; `stopped` says whether it already has. Returns
// why the run stopped (a target found, a limit), if it did.
template <class Hooks, class AfterBatch>
std::optional<StopReason> insert_start_states(const tioa::StartSet& start, Exploration& ex,
                                              const Hooks& hooks, Insertion& insertion,
                                              AfterBatch&& after_batch) {
  struct StopEnumeration {};
  const std::uint32_t words = ex.state_words;
  std::optional<StopReason> stop;
  std::vector<Word> buffer(words + 1, 0), representative(words + 1, 0);
  std::vector<Word> batch;
  std::vector<std::uint64_t> hashes, fingerprints; // (the fingerprint store's keys)
  auto insert_batch = [&] {
    for (std::size_t b = 0; b < hashes.size(); ++b)
      ex.store.prefetch(hashes[b]);
    for (std::size_t b = 0; b < hashes.size() && !stop; ++b) {
      const Word* state = batch.data() + b * words;
      const StoreKey key{ex.fingerprints() ? &fingerprints[b] : state, hashes[b]};
      const auto [outcome, id] = insertion.insert(state, key, no_parent);
      if (outcome == Insertion::Outcome::state_limit) {
        stop = StopReason::state_limit;
      } else if (outcome == Insertion::Outcome::memory_limit) {
        stop = StopReason::memory_limit;
      } else if (outcome == Insertion::Outcome::fresh) {
        ++ex.start_states;
        if (is_target(hooks, state)) {
          ex.found = id;
          if (ex.fingerprints())
            ex.found_state.assign(state, state + words);
          stop = StopReason::found;
        }
      }
    }
    batch.clear();
    hashes.clear();
    fingerprints.clear();
    if (const auto reason = after_batch(stop.has_value()); reason && !stop)
      stop = reason;
  };
  try {
    start.enumerate(buffer.data(), 0, [&] {
      const Word* state = buffer.data();
      if (canonicalises(hooks)) { // on a copy: the enumeration goes on from `buffer`
        std::copy(buffer.begin(), buffer.end(), representative.begin());
        canonicalise(hooks, representative.data());
        state = representative.data();
      }
      batch.insert(batch.end(), state, state + words);
      std::uint64_t fingerprint_of = 0;
      hashes.push_back(store_key(state, words, ex.fingerprints(), fingerprint_of).hash);
      fingerprints.push_back(fingerprint_of);
      if (hashes.size() == start_batch) {
        insert_batch();
        if (stop)
          throw StopEnumeration{};
      }
    });
    insert_batch();
  } catch (const StopEnumeration&) {
  }
  return stop;
}

} // namespace checker
