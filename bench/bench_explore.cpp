// Exploration speed on the two peer models and on path-reservation: states, edges, seconds, states
// per second, peak memory and thread count for each size. Run: build/bench/bench_explore [--threads
// N]
// [--quick]. Counts are checked against the same exploration on every run (they must not
// depend on the thread count); speed is only printed, never asserted.

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "checker/explorer.hpp"
#include "models/fischer/fischer.hpp"
#include "models/path_reservation/protocol.hpp"
#include "models/token_ring/token_ring.hpp"

namespace {

long peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;
}

void run(const std::string& name, const tioa::Automaton& system, unsigned threads) {
  const tioa::SuccessorGenerator generator(system);
  checker::ExploreOptions options;
  options.threads = threads;
  const checker::Exploration ex = checker::explore(generator, system.start(), options);
  std::printf("%-28s %12llu %13llu %8.2f %10.2f %8ld %7u\n", name.c_str(),
              static_cast<unsigned long long>(ex.store.size()),
              static_cast<unsigned long long>(ex.edges), ex.seconds,
              static_cast<double>(ex.store.size()) / ex.seconds / 1e6, peak_memory_mib(), threads);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
  unsigned threads = 2;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc)
      threads = static_cast<unsigned>(std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
  }
  std::printf("%-28s %12s %13s %8s %10s %8s %7s\n", "instance", "states", "edges", "seconds",
              "Mstates/s", "peakMiB", "threads");
  const std::vector<std::pair<int, int>> rings =
      quick ? std::vector<std::pair<int, int>>{{7, 6}}
            : std::vector<std::pair<int, int>>{{7, 6}, {8, 7}, {9, 6}, {10, 5}};
  for (auto [n, k] : rings)
    run("token-ring N=" + std::to_string(n) + " K=" + std::to_string(k),
        token_ring::build(n, k).system, threads);
  const int max_fischer = quick ? 5 : 7;
  for (int n = 4; n <= max_fischer; ++n)
    run("fischer N=" + std::to_string(n) + " A=1 B=2", fischer::build(n, 1, 2).system, threads);
  // The scenarios of seed 004 with three and four robots; pinwheel is the one the suite
  // leaves to a unit test.
  const std::vector<const char*> scenarios =
      quick ? std::vector<const char*>{"late-joiner"}
            : std::vector<const char*>{"late-joiner", "cycle", "pinwheel"};
  for (const char* scenario : scenarios)
    run(std::string("path-reservation ") + scenario,
        path_reservation::build_protocol(path_reservation::find_scenario(scenario), {}).system,
        threads);
  return 0;
}
