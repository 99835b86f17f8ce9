#pragma once
// A small, fixed, portable generator (SplitMix64, Steele, Lea and Flood 2014) for the
// seeded random searches of proofs/: the same seed draws the same numbers on every
// platform and standard library, so a search and its counterexamples reproduce.

#include <cstdint>
#include <stdexcept>

namespace proofs {

class SplitMix64 {
public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  // Uniform in 0..bound-1 (bound >= 1), by rejection: the same numbers on every platform.
  std::uint64_t below(std::uint64_t bound) {
    if (bound == 0)
      throw std::invalid_argument("SplitMix64::below(0)");
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % bound; // accept [0, limit)
    for (;;)
      if (const std::uint64_t x = next(); x < limit)
        return x % bound;
  }

private:
  std::uint64_t state_;
};

} // namespace proofs
