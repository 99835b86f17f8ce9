#pragma once
// The hash of a packed state: a multiply-xorshift over the words, finished with the
// SplitMix64 mixer. The checker's store keys states by it; a model may hash its own words
// (a relation's key) with the same function.

#include <cstdint>

#include "tioa/variables.hpp"

namespace tioa {

inline std::uint64_t hash_state(const Word* state, std::uint32_t words) {
  std::uint64_t h = 0x243f6a8885a308d3ull;
  for (std::uint32_t i = 0; i < words; ++i)
    h = (h ^ (h >> 31) ^ state[i]) * 0x9e3779b97f4a7c15ull;
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

} // namespace tioa
