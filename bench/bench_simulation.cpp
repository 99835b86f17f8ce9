// The whole sweep of seed 002 §VII (models/mc/simulation.hpp): m = 10..20, the curves C1,
// C2, C3, 10^5 robots from the lower-right region, e = 5, σ = 1/4, ρ2 = 9/10. Prints, per
// (m, curve), the seconds spent quantising the curve and running to the fixed point, the
// rounds computed and T_out / T_stab; then the total. Run: build/bench/bench_simulation
// [--nbh 4|8] [--quick] (--quick: m = 10..12). Speed is only printed, never asserted.

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "models/mc/simulation.hpp"

int main(int argc, char** argv) {
  mc::SimulationSetup setup;
  int m_to = 20;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--nbh") == 0 && i + 1 < argc)
      setup.neighbourhood =
          std::strcmp(argv[++i], "8") == 0 ? mc::Neighbourhood::eight : mc::Neighbourhood::four;
    else if (std::strcmp(argv[i], "--quick") == 0)
      m_to = 12;
  }
  std::printf("%-3s %-5s %9s %9s %8s %7s %7s\n", "m", "curve", "curve s", "run s", "rounds",
              "T_out", "T_stab");
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double curve_total = 0, run_total = 0;
  std::size_t rounds = 0;
  for (int m = 10; m <= m_to; ++m) {
    for (const std::string& curve : mc::simulation_curve_names()) {
      const mc::SimulationCase instance = mc::prepare_case(m, curve, setup);
      const mc::SimulationResult result = mc::run_case(instance, setup);
      const double run = result.seconds - instance.seconds;
      curve_total += instance.seconds;
      run_total += run;
      rounds += result.rounds;
      std::printf("%-3d %-5s %9.4f %9.4f %8zu %7zu %7zu\n", m, curve.c_str(), instance.seconds, run,
                  result.rounds, result.t_out, result.t_stab);
      std::fflush(stdout);
    }
  }
  const double total = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("total: %.3f s (curves %.3f s, runs %.3f s), %zu rounds, %.1f µs per round, "
              "%d-neighbourhood\n",
              total, curve_total, run_total, rounds, run_total / static_cast<double>(rounds) * 1e6,
              static_cast<int>(setup.neighbourhood));
  return 0;
}
