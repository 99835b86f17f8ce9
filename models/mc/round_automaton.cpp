#include "models/mc/round_automaton.hpp"

#include <memory>
#include <stdexcept>

namespace mc {

Counts counts_of(const tioa::VariableArray<int>& y, const tioa::State& s) {
  Counts counts(y.size());
  for (std::size_t u = 0; u < y.size(); ++u)
    counts[u] = s[y[u]];
  return counts;
}

namespace {

// The automaton with y[u] in 0..most, its start set still to be set.
RoundAutomaton round_steps(const RoundSystem& system, RobotCount most) {
  RoundAutomaton out{tioa::Automaton("mc-round"), {}};
  out.y =
      out.automaton.integers("y", system.grid().size(), 0, static_cast<int>(most), std::nullopt);
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
  return out;
}

} // namespace

RoundAutomaton round_automaton(const RoundSystem& system, RobotCount start_max) {
  // Robots are conserved, so no region ever holds more than all of them.
  RoundAutomaton out =
      round_steps(system, start_max * static_cast<RobotCount>(system.grid().size()));
  const auto y = out.y;
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

RoundAutomaton round_automaton(const RoundSystem& system, const Counts& start) {
  if (start.size() != system.grid().size())
    throw std::invalid_argument("the start has " + std::to_string(start.size()) +
                                " regions, the grid " + std::to_string(system.grid().size()));
  const RobotCount robots = total(start);
  if (robots > max_automaton_robots)
    throw std::invalid_argument("the round automaton holds at most " +
                                std::to_string(max_automaton_robots) + " robots, not " +
                                std::to_string(robots));
  RoundAutomaton out = round_steps(system, robots);
  const auto y = out.y;
  out.automaton.set_start(tioa::StartSet(
      "the given configuration of " + std::to_string(robots) + " robots",
      [y, start](tioa::Word* words, std::uint32_t base, const tioa::StartSet::Visit& visit) {
        tioa::State s(words, base);
        for (std::size_t u = 0; u < y.size(); ++u)
          s[y[u]] = static_cast<int>(start[u]);
        visit();
      }));
  return out;
}

} // namespace mc
