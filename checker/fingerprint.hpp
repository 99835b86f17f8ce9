#pragma once
// The fingerprint store (ExploreOptions::store = StoreKind::fingerprint), as TLC has it: the
// visited set keeps a 64-bit fingerprint per state instead of the state. It is the same
// StateStore, over one-word "states" that are the fingerprints: the table still holds
// 32-bit tagged ids, and the arena the fingerprints in id order (8 bytes per state
// whatever the width of a state), so growth, concurrent insertion and the breadth-first
// numbering are those of the exact store. The full states live only for the frontier
// being expanded and the level being built (level_states.hpp).
//
// Two distinct states with one fingerprint count as one: the second is never expanded, and
// what only it leads to is missed. So a search that finds nothing says "holds up to hash
// collisions"; a violation it finds is real (its trace is rebuilt by re-execution and
// replays, trace.hpp).

#include <cstdint>

#include "tioa/variables.hpp"

namespace checker {

// A 64-bit hash of the state's words, independent of hash_state (another seed, other
// multipliers, MurmurHash3's finaliser instead of SplitMix64's): the store's table hashes
// the fingerprint again with hash_state, so the table's home slots and the fingerprints
// do not share their bits.
inline std::uint64_t fingerprint(const tioa::Word* state, std::uint32_t words) {
  std::uint64_t h = 0x452821e638d01377ull;
  for (std::uint32_t i = 0; i < words; ++i)
    h = (h ^ (h >> 29) ^ state[i]) * 0xc2b2ae3d27d4eb4full;
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  return h ^ (h >> 33);
}

// The probability that two of `states` distinct states share a fingerprint, taking
// fingerprints as uniform and independent 64-bit values (the birthday bound):
//
//   p <= n (n - 1) / 2 / 2^64
//
// A state is missed only if such a collision happens, so this bounds the probability that
// a state was missed, with n the number of distinct states the search visited taken for
// the number of reachable states (as TLC's estimate does: when a state was missed, the
// reachable states are more than the visited ones).
inline double omission_probability(std::uint64_t states) {
  const double n = static_cast<double>(states);
  return states < 2 ? 0.0 : n * (n - 1) / 2 / 18446744073709551616.0;
}

} // namespace checker
