// What a second thread gives on this machine at all, with no model checker in the way:
// the speed-up of two threads over one on (a) a loop of arithmetic that stays in
// registers and (b) random reads of a 512 MiB table, the store's lookups (most of them
// find a state). The explorer's speed-up on Fischer (issue 14 asks 1.8x) is bounded by (b).
//
//   build/bench/thread_ceiling [rounds]
//
// Each round runs one thread, then two threads on the same total work, and prints both
// speed-ups; on a shared virtual machine they move from round to round.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr std::uint64_t table_bits = 27; // 2^27 four-byte entries
constexpr std::uint64_t arithmetic_steps = 400'000'000;
constexpr std::uint64_t random_accesses = 60'000'000;

std::uint64_t arithmetic(std::uint64_t steps) {
  std::uint64_t x = 1;
  for (std::uint64_t i = 0; i < steps; ++i) {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    x ^= x >> 13;
  }
  return x;
}

std::uint64_t random_reads(const std::vector<std::uint32_t>& table, std::uint64_t accesses,
                           std::uint64_t seed) {
  std::uint64_t x = seed, sum = 0;
  const std::uint64_t mask = (std::uint64_t{1} << table_bits) - 1;
  for (std::uint64_t i = 0; i < accesses; ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    sum += table[x & mask]; // (independent reads: several misses in flight)
  }
  return sum;
}

// Seconds for `threads` threads, thread t running work(t).
template <class Work> double timed(unsigned threads, Work work) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> running;
  for (unsigned t = 0; t < threads; ++t)
    running.emplace_back([&, t] { work(t); });
  for (std::thread& thread : running)
    thread.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  std::vector<std::uint32_t> table(std::size_t{1} << table_bits, 1);
  std::atomic<std::uint64_t> sink{0}; // keeps the work from being optimised away
  std::printf("%-6s %22s %22s\n", "round", "arithmetic 1t/2t (x)", "random 1t/2t (x)");
  for (int round = 1; round <= rounds; ++round) {
    const double a1 = timed(1, [&](unsigned) { sink += arithmetic(arithmetic_steps); });
    const double a2 = timed(2, [&](unsigned) { sink += arithmetic(arithmetic_steps / 2); });
    const double r1 =
        timed(1, [&](unsigned t) { sink += random_reads(table, random_accesses, t + 1); });
    const double r2 =
        timed(2, [&](unsigned t) { sink += random_reads(table, random_accesses / 2, t + 11); });
    std::printf("%-6d %7.2f/%.2f s (%.2fx) %7.2f/%.2f s (%.2fx)\n", round, a1, a2, a1 / a2, r1, r2,
                r1 / r2);
  }
  return sink.load() == 42 ? 1 : 0;
}
