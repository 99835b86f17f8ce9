#include "models/path_reservation/random_scenario.hpp"

#include <random>
#include <stdexcept>
#include <vector>

namespace path_reservation {

namespace {

constexpr int draws = 10000;

// The cells a chunk of `plane` from `from` may end on: straight (8 directions), inside the
// plane, and inside the closed disk Cir(from, C/2) (Definition 4).
std::vector<Cell> chunk_ends(const Plane& plane, int range, Cell from) {
  std::vector<Cell> out;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int length = 1; (dx != 0 || dy != 0) && length <= range; ++length) {
        const Cell to{from.x + dx * length, from.y + dy * length};
        if (!plane.contains(to))
          break;
        if ((plane.zone(from, to).all() & ~plane.disk(from, range * range)) != 0)
          break;
        out.push_back(to);
      }
  return out;
}

// Whether the robots whose paths share a cell form one connected group.
bool connected(const Plane& plane, const std::vector<std::vector<Cell>>& paths) {
  std::vector<CellSet> covered;
  for (const auto& path : paths) {
    CellSet cells = 0;
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
      cells |= plane.zone(path[k], path[k + 1]).all();
    covered.push_back(cells);
  }
  std::vector<bool> reached(paths.size(), false);
  std::vector<std::size_t> todo{0};
  reached[0] = true;
  while (!todo.empty()) {
    const std::size_t r = todo.back();
    todo.pop_back();
    for (std::size_t other = 0; other < paths.size(); ++other)
      if (!reached[other] && (covered[r] & covered[other]) != 0) {
        reached[other] = true;
        todo.push_back(other);
      }
  }
  for (const bool r : reached)
    if (!r)
      return false;
  return true;
}

} // namespace

Scenario random_scenario(const RandomScenarioSpec& spec) {
  if (spec.robots < 1 || spec.robots > max_robots)
    throw std::invalid_argument("robots must be in 1.." + std::to_string(max_robots));
  if (spec.chunks < 1 || spec.chunks > max_chunks)
    throw std::invalid_argument("chunks must be in 1.." + std::to_string(max_chunks));
  if (spec.plane < 2 || spec.plane > 8)
    throw std::invalid_argument("plane must be in 2..8 (a side of at most 8 cells: 64 cells)");
  if (spec.robots > spec.plane * spec.plane)
    throw std::invalid_argument("more robots than cells");
  const Plane plane(spec.plane, spec.plane);
  const int range = spec.plane;
  std::mt19937_64 random(spec.seed);
  const auto pick = [&](std::size_t count) {
    return std::uniform_int_distribution<std::size_t>(0, count - 1)(random);
  };
  for (int draw = 0; draw < draws; ++draw) {
    Scenario s;
    s.name = "random-" + std::to_string(spec.seed);
    s.description = "drawn at random: seed " + std::to_string(spec.seed) + ", " +
                    std::to_string(spec.robots) + " robots, " + std::to_string(spec.chunks) +
                    " chunks each, a " + std::to_string(spec.plane) + "x" +
                    std::to_string(spec.plane) + " plane, C = " + std::to_string(range);
    s.width = s.height = spec.plane;
    s.range = range;
    CellSet starts = 0, ends = 0;
    bool valid = true;
    for (int r = 0; r < spec.robots && valid; ++r) {
      Cell at = plane.cell(static_cast<int>(pick(static_cast<std::size_t>(plane.cells()))));
      valid = (starts & plane.bit(at)) == 0;
      starts |= plane.bit(at);
      std::vector<Cell> path{at};
      for (int k = 0; k < spec.chunks && valid; ++k) {
        const auto ends_here = chunk_ends(plane, range, at);
        valid = !ends_here.empty();
        if (valid)
          at = ends_here[pick(ends_here.size())];
        path.push_back(at);
      }
      valid = valid && (ends & plane.bit(at)) == 0;
      ends |= plane.bit(at);
      s.paths.push_back(path);
    }
    if (valid && connected(plane, s.paths) && !check_scenario(s))
      return s;
  }
  throw std::invalid_argument("no valid scenario in " + std::to_string(draws) +
                              " draws for these sizes (a larger plane, or fewer robots)");
}

} // namespace path_reservation
