#include "models/mc/round_automaton.hpp"

#include <memory>

namespace mc {

Counts counts_of(const tioa::VariableArray<int>& y, const tioa::State& s) {
  Counts counts(y.size());
  for (std::size_t u = 0; u < y.size(); ++u)
    counts[u] = s[y[u]];
  return counts;
}

RoundAutomaton round_automaton(const RoundSystem& system, RobotCount start_max) {
  const std::size_t regions = system.grid().size();
  const RobotCount total_max = start_max * static_cast<RobotCount>(regions);
  RoundAutomaton out{tioa::Automaton("mc-round"), {}};
  // Robots are conserved, so no region ever holds more than all of them.
  out.y = out.automaton.integers("y", regions, 0, static_cast<int>(total_max), std::nullopt);

  const auto y = out.y;
  auto sys = std::make_shared<const RoundSystem>(system);
  out.automaton.internal("round").choose(
      [y, sys](const tioa::State& s, const tioa::Params&) {
        return static_cast<std::uint32_t>(sys->all_next(counts_of(y, s)).size());
      },
      [y, sys](tioa::State& s, const tioa::Params&, std::uint32_t choice) {
        const Counts next = sys->all_next(counts_of(y, s)).at(choice);
        for (std::size_t u = 0; u < next.size(); ++u)
          s[y[u]] = static_cast<int>(next[u]);
      });

  out.automaton.set_start(tioa::StartSet(
      "every distribution of at most " + std::to_string(start_max) + " robots per region",
      [y, start_max](tioa::Word* words, std::uint32_t base, const tioa::StartSet::Visit& visit) {
        tioa::State s(words, base);
        std::function<void(std::size_t)> region = [&](std::size_t u) {
          if (u == y.size()) {
            visit();
            return;
          }
          for (RobotCount count = 0; count <= start_max; ++count) {
            s[y[u]] = static_cast<int>(count);
            region(u + 1);
          }
        };
        region(0);
      }));
  return out;
}

} // namespace mc
