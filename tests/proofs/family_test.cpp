// The declared family of round-level instances (proofs/family.hpp): the curves, the
// symmetries of the square, the enumeration with one configuration per orbit, and the
// counts of what a family covers.
#include <catch2/catch.hpp>

#include <map>
#include <numeric>

#include "proofs/family.hpp"

using namespace proofs;

namespace {

// Orbits of the configurations with counts 0..c on an m×m grid under the symmetries fixing
// q, by Burnside's lemma: the average over the group of (c+1)^(cycles of σ).
std::uint64_t burnside(int m, const std::vector<QuantisedLength>& q, std::uint64_t c) {
  const auto group = symmetries_fixing(m, q);
  std::uint64_t sum = 0;
  for (const auto& sigma : group) {
    std::vector<bool> seen(sigma.size(), false);
    std::uint64_t fixed = 1;
    for (std::size_t u = 0; u < sigma.size(); ++u) {
      if (seen[u])
        continue;
      for (std::size_t v = u; !seen[v]; v = sigma[v])
        seen[v] = true;
      fixed *= c + 1;
    }
    sum += fixed;
  }
  return sum / group.size();
}

Family tiny(mc::Neighbourhood nbh) {
  Family f;
  f.sides = {{1, 3}, {2, 3}, {3, 1}};
  f.neighbourhoods = {nbh};
  f.ks = {1};
  f.rho2s = {{9, 10}};
  return f;
}

} // namespace

TEST_CASE("family: the named curves as q matrices", "[proofs][family]") {
  using Q = std::vector<QuantisedLength>;
  CHECK(curve_q("none", 3) == Q{0, 0, 0, 0, 0, 0, 0, 0, 0});
  CHECK(curve_q("point", 3) == Q{0, 0, 0, 0, 1, 0, 0, 0, 0});
  CHECK(curve_q("line", 3) == Q{0, 0, 0, 1, 1, 1, 0, 0, 0});
  CHECK(curve_q("L", 3) == Q{1, 0, 0, 1, 0, 0, 1, 1, 1});
  CHECK(curve_q("ring", 3) == Q{1, 1, 1, 1, 0, 1, 1, 1, 1});
  CHECK(curve_q("all", 3) == Q{1, 1, 1, 1, 1, 1, 1, 1, 1});
  CHECK(curve_q("line-1-3", 3) == Q{0, 0, 0, 1, 3, 1, 0, 0, 0});
  CHECK(curve_q("checker-1-3", 3) == Q{1, 3, 1, 3, 1, 3, 1, 3, 1});
  CHECK(curve_q("hub-3", 3) == Q{1, 1, 1, 1, 3, 1, 1, 1, 1});
  CHECK(curve_q("ring", 2) == Q{1, 1, 1, 1});
  CHECK(curve_q("line", 2) == Q{0, 0, 1, 1});
  CHECK_THROWS_WITH(curve_q("spiral", 3), Catch::Contains("unknown curve 'spiral'"));
  CHECK_THROWS_AS(curve_q("none", 0), std::invalid_argument);
}

TEST_CASE("family: the symmetries of the square", "[proofs][family]") {
  CHECK(grid_symmetries(1).size() == 1);
  CHECK(grid_symmetries(2).size() == 8);
  CHECK(grid_symmetries(3).size() == 8);
  for (const auto& sigma : grid_symmetries(3)) { // permutations of the 9 regions
    auto sorted = sigma;
    std::sort(sorted.begin(), sorted.end());
    std::vector<RegionId> ids(9);
    std::iota(ids.begin(), ids.end(), 0);
    CHECK(sorted == ids);
  }
  // Which symmetries fix each curve on 3×3.
  const std::map<std::string, std::size_t> expected{
      {"none", 8}, {"point", 8},    {"line", 4},        {"L", 2},    {"ring", 8},
      {"all", 8},  {"line-1-3", 4}, {"checker-1-3", 8}, {"hub-3", 8}};
  for (const auto& [name, size] : expected)
    CHECK(symmetries_fixing(3, curve_q(name, 3)).size() == size);
  // Both neighbourhoods are invariant: σ maps neighbours to neighbours.
  for (auto nbh : {mc::Neighbourhood::four, mc::Neighbourhood::eight}) {
    const mc::GridTiling grid(3, nbh);
    for (const auto& sigma : grid_symmetries(3))
      for (RegionId u = 0; u < 9; ++u)
        for (RegionId v = 0; v < 9; ++v)
          CHECK(grid.neighbours(u, v) == grid.neighbours(sigma[u], sigma[v]));
  }
}

TEST_CASE("family: one configuration per orbit, as many as Burnside counts", "[proofs][family]") {
  for (int m : {1, 2, 3})
    for (const auto& name : curve_names()) {
      Setting s;
      s.m = m;
      s.q = curve_q(name, m);
      s.max_count = m == 3 ? 2 : 3;
      std::uint64_t represented = 0;
      const Coverage c = for_each_configuration(
          s, true, [&](const Counts&, std::uint64_t orbit) { represented += orbit; });
      const auto regions = static_cast<std::uint64_t>(m * m);
      std::uint64_t all = 1;
      for (std::uint64_t i = 0; i < regions; ++i)
        all *= static_cast<std::uint64_t>(s.max_count + 1);
      CHECK(c.visited == burnside(m, s.q, static_cast<std::uint64_t>(s.max_count)));
      CHECK(c.total() == all);
      CHECK(represented == all);
      const Coverage plain = for_each_configuration(s, false, [](const Counts&, auto) {});
      CHECK(plain.visited == all);
      CHECK(plain.skipped == 0);
    }
  // 2×2, no curve, counts 0..3: 256 configurations in 55 orbits.
  Setting s;
  s.m = 2;
  s.q = curve_q("none", 2);
  s.max_count = 3;
  const Coverage c = for_each_configuration(s, true, [](const Counts&, auto) {});
  CHECK(c.visited == 55);
  CHECK(c.skipped == 201);
}

TEST_CASE("family: settings, merged curves and the description", "[proofs][family]") {
  const Family f = tiny(mc::Neighbourhood::eight);
  const SettingList list = settings(f);
  // m = 1: none, point (q = 1), hub-3 (q = 3); m = 2: all but "all" (= ring); m = 3: all 9.
  CHECK(list.settings.size() == 3 + 8 + 9);
  CHECK(list.merged == std::vector<std::string>{
                           "line = point (m = 1)", "L = point (m = 1)", "ring = point (m = 1)",
                           "all = point (m = 1)", "line-1-3 = point (m = 1)",
                           "checker-1-3 = point (m = 1)", "all = ring (m = 2)"});
  CHECK(describe(list.settings.back()) ==
        "m = 3, neighbourhood 8, curve hub-3, k = 1, rho2 = 9/10");
  const std::string text = describe(f);
  CHECK_THAT(text, Catch::Contains("m in {1 (counts 0..3), 2 (counts 0..3), 3 (counts 0..1)}"));
  CHECK_THAT(text, Catch::Contains("neighbourhood 8"));
  CHECK_THAT(text, Catch::Contains("rho2 in {9/10}"));
  const Coverage c = count_configurations(f);
  // m = 1: 3 curves × 4; m = 2 (by Burnside): none 55, point 160, line 136, L 160, ring 55,
  // line-1-3 256, checker-1-3 100, hub-3 160; m = 3 (counts 0..1): 1236.
  CHECK(c.visited == 12 + 1082 + 1236);
  CHECK(c.total() == 3 * 4 + 8 * 256 + 9 * 512);
}

TEST_CASE("family: bad families are refused", "[proofs][family]") {
  Family f;
  f.ks = {0};
  CHECK_THROWS_AS(settings(f), std::invalid_argument);
  f = Family{};
  f.rho2s = {{1, 1}};
  CHECK_THROWS_AS(settings(f), std::invalid_argument);
  f = Family{};
  f.curves = {"spiral"};
  CHECK_THROWS_AS(settings(f), std::invalid_argument);
  f = Family{};
  f.sides = {};
  CHECK_THROWS_AS(settings(f), std::invalid_argument);
}

TEST_CASE("family: matrices print row by row", "[proofs][family]") {
  CHECK(matrix_lines(2, {0, 12, 3, 0}, "  ", true) ==
        std::vector<std::string>{"   . 12", "   3  ."});
  CHECK(region_name(3, 5) == "(1,2)");
}
