// The simulation of seed 002 §VII (models/mc/simulation.hpp): two runs followed by hand
// round by round; the paper's setting at m = 10 with T_out and T_stab pinned and
// recomputed another way from the whole run (counts of the Out regions, the first
// repeated matrix), conservation and the fixed point being fixed for every order; the
// claim about C2 at its threshold; the CSV; the SVG figures parsed as XML.
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <sstream>
#include <string>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include "models/mc/simulation.hpp"

using namespace mc;

namespace {

SimulationSetup small_setup(RobotCount robots) {
  SimulationSetup setup;
  setup.robots = robots;
  return setup; // e = 5, ρ2 = 9/10, σ = 1/4, 4-neighbourhood: the defaults of the sweep
}

// The whole run of one case, every M_t kept.
FixpointRun full_run(const SimulationCase& instance, const SimulationSetup& setup) {
  McParams params;
  params.k = setup.e;
  params.rho2 = setup.rho2;
  const RoundSystem system(GridTiling(instance.m, setup.neighbourhood), instance.q, params);
  return system.run_to_fixpoint(corner_start(instance.m, setup.robots));
}

boost::property_tree::ptree parse_xml(const std::string& text) {
  std::istringstream in(text);
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(in, tree); // throws xml_parser_error when malformed
  return tree;
}

// How many elements named `name` the tree holds, at any depth.
std::size_t count_elements(const boost::property_tree::ptree& tree, const std::string& name) {
  std::size_t n = 0;
  for (const auto& [key, child] : tree)
    n += (key == name ? 1 : 0) + count_elements(child, name);
  return n;
}

} // namespace

TEST_CASE("simulation: the corner start and the curves' q on the 3×3 grid", "[mc][simulation]") {
  CHECK(corner_start(3, 30) == Counts{0, 0, 0, 0, 0, 0, 0, 0, 30});
  const SimulationSetup setup = small_setup(30);
  // C1: the unit square through the centres of (1,1), (1,2), (2,1), (2,2); b of it in each,
  // q = b/σ = 4. C2: the same at the top-left.
  CHECK(prepare_case(3, "C1", setup).q == std::vector<QuantisedLength>{0, 0, 0, 0, 4, 4, 0, 4, 4});
  CHECK(prepare_case(3, "c2", setup).q == std::vector<QuantisedLength>{4, 4, 0, 4, 4, 0, 0, 0, 0});
  CHECK(prepare_case(3, "c2", setup).curve == "C2");
  const std::vector<double> target = target_distribution(prepare_case(3, "C1", setup).q, 30);
  CHECK(target == std::vector<double>{0, 0, 0, 0, 7.5, 7.5, 0, 7.5, 7.5});
}

TEST_CASE("simulation: C1 on 3×3 with 30 robots, followed by hand", "[mc][simulation]") {
  // Regions 4 (1,1), 5 (1,2), 7 (2,1), 8 (2,2) are on the curve, q = 4 each; e = 5.
  //   round 0: 8 (y 30): lower {5, 7}, ⌊0.9·(4·30 − 4·0)/(4·2·3)⌋ = ⌊4.5⌋ = 4 each
  //   round 1: 8 (22): ⌊0.9·4·18/24⌋ = 2 each; 5 and 7 hold 4 ≤ e
  //   round 2: 5 (6): lower {4} (not 8: 6 < 18): ⌊0.9·24/16⌋ = 1, cap n − e = 1; 7 the same;
  //            8 (18): ⌊0.9·4·12/24⌋ = 1 each
  //   round 3: 5 (6) vs 4 (2): ⌊0.9·16/16⌋ = 0; 8 (16): ⌊0.9·40/24⌋ = 1 each
  //   round 4: 5 (7) vs 4 (2): ⌊0.9·20/16⌋ = 1; 7 the same; 8 (14): ⌊0.9·28/24⌋ = 1 each
  //   round 5: 5 (7) vs 4 (4): ⌊0.9·12/16⌋ = 0; 8 (12): ⌊0.9·20/24⌋ = 0: nothing moves.
  const SimulationSetup setup = small_setup(30);
  const SimulationCase instance = prepare_case(3, "C1", setup);
  const FixpointRun run = full_run(instance, setup);
  CHECK(run.rounds == std::vector<Counts>{{0, 0, 0, 0, 0, 0, 0, 0, 30},
                                          {0, 0, 0, 0, 0, 4, 0, 4, 22},
                                          {0, 0, 0, 0, 0, 6, 0, 6, 18},
                                          {0, 0, 0, 0, 2, 6, 0, 6, 16},
                                          {0, 0, 0, 0, 2, 7, 0, 7, 14},
                                          {0, 0, 0, 0, 4, 7, 0, 7, 12}});
  const SimulationResult result = run_case(instance, setup, true);
  CHECK(result.t_out == 0); // no region off the curve ever has a robot
  CHECK(result.t_stab == 5);
  CHECK(result.rounds == 6);
  CHECK(result.off_curve == 0);
  REQUIRE(result.snapshots.size() == 3);
  CHECK(result.snapshots[0].round == 1);
  CHECK(result.snapshots[0].counts == run.rounds[1]);
  CHECK(result.snapshots[1].round == 0);
  CHECK(result.snapshots[1].counts == run.rounds[0]);
  CHECK(result.snapshots[2].round == 5);
  CHECK(result.snapshots[2].counts == run.rounds[5]);
}

TEST_CASE("simulation: C2 on 3×3 with 30 robots, followed by hand", "[mc][simulation]") {
  // In = {0, 1, 3, 4} (q = 4). Region 8 has no curve neighbour (line 14); 5 and 7 are on the
  // boundary (lines 19–22) and send ⌊(y − e)/|In|⌋ = y − 5 to region 4.
  //   round 0: 8 (30): lower {5, 7}: ⌊0.9·30/6⌋ = 4 each
  //   round 1: 8 (22): ⌊0.9·18/6⌋ = 2 each
  //   round 2: 5, 7 (6): 1 each to 4; 8 (18): ⌊0.9·12/6⌋ = 1 each
  //   round 3: the same (8: ⌊0.9·10/6⌋ = 1)      round 4: the same (8: ⌊0.9·8/6⌋ = 1)
  //   round 5: 4 (6): lower {1, 3}, ⌊0.9·24/24⌋ = 0; 5, 7: 1 each to 4; 8 (12): ⌊0.9·6/6⌋ = 0
  //   round 6: 4 (8): ⌊0.9·32/24⌋ = 1 to 1 and to 3; 8 (12) vs 5: ⌊0.9·7/6⌋ = 1 each
  //   round 7: 4 (6): ⌊0.9·20/24⌋ = 0; 5, 7 (6): 1 each to 4 — the last move off the curve
  //   round 8: 4 (8): ⌊0.9·28/24⌋ = 1 to 1 and to 3 — the last move
  //   round 9: 4 (6): ⌊0.9·16/24⌋ = 0; 8 (10) vs 5: ⌊0.9·5/6⌋ = 0: nothing moves.
  const SimulationSetup setup = small_setup(30);
  const SimulationCase instance = prepare_case(3, "C2", setup);
  const FixpointRun run = full_run(instance, setup);
  CHECK(run.rounds == std::vector<Counts>{{0, 0, 0, 0, 0, 0, 0, 0, 30},
                                          {0, 0, 0, 0, 0, 4, 0, 4, 22},
                                          {0, 0, 0, 0, 0, 6, 0, 6, 18},
                                          {0, 0, 0, 0, 2, 6, 0, 6, 16},
                                          {0, 0, 0, 0, 4, 6, 0, 6, 14},
                                          {0, 0, 0, 0, 6, 6, 0, 6, 12},
                                          {0, 0, 0, 0, 8, 5, 0, 5, 12},
                                          {0, 1, 0, 1, 6, 6, 0, 6, 10},
                                          {0, 1, 0, 1, 8, 5, 0, 5, 10},
                                          {0, 2, 0, 2, 6, 5, 0, 5, 10}});
  const SimulationResult result = run_case(instance, setup);
  CHECK(result.t_out == 8);
  CHECK(result.t_stab == 9);
  CHECK(result.rounds == 10);
  CHECK(result.off_curve == 20); // 5 + 5 + 10 stay off the curve: e and the floors stop them
  CHECK(result.snapshots.empty());
}

TEST_CASE("simulation: the paper's setting at m = 10, pinned and cross-checked",
          "[mc][simulation]") {
  // e = 5, 10^5 robots in region (9,9), σ = 1/4, ρ2 = 9/10, 4-neighbourhood.
  const SimulationSetup setup; // the defaults are the paper's and ours
  REQUIRE(setup.robots == 100'000);
  REQUIRE(setup.e == 5);
  struct Pinned {
    const char* curve;
    std::size_t t_out, t_stab;
    RobotCount off_curve;
  };
  for (const Pinned& pinned :
       {Pinned{"C1", 0, 138, 0}, Pinned{"C2", 1087, 1090, 2022}, Pinned{"C3", 165, 223, 608}}) {
    INFO(pinned.curve);
    const SimulationCase instance = prepare_case(10, pinned.curve, setup);
    const SimulationResult result = run_case(instance, setup, true);
    CHECK(result.t_out == pinned.t_out);
    CHECK(result.t_stab == pinned.t_stab);
    CHECK(result.rounds == pinned.t_stab + 1);
    CHECK(result.off_curve == pinned.off_curve);

    // The same numbers another way, from every M_t of the run.
    const FixpointRun run = full_run(instance, setup);
    const std::vector<Counts>& M = run.rounds;
    REQUIRE(M.size() == result.t_stab + 1);
    for (const Counts& counts : M)
      REQUIRE(total(counts) == setup.robots); // conservation
    // T_stab: the first t with M_{t+1} = M_t, and M_t really is fixed, for every order of
    // every lower set.
    CHECK(M[M.size() - 2] != M.back());
    McParams params;
    params.k = setup.e;
    params.rho2 = setup.rho2;
    const RoundSystem system(GridTiling(10, setup.neighbourhood), instance.q, params);
    CHECK(system.all_next(M.back()) == std::vector<Counts>{M.back()});
    // T_out: 1 + the last round in which the count of a region off the curve changes.
    std::size_t last_change = 0;
    for (std::size_t t = 0; t + 1 < M.size(); ++t)
      for (std::size_t u = 0; u < instance.q.size(); ++u)
        if (instance.q[u] == 0 && M[t + 1][u] != M[t][u])
          last_change = t + 1;
    CHECK(last_change == result.t_out);
    // The robots off the curve at the end, and Fig. 8's snapshots.
    RobotCount off = 0;
    for (std::size_t u = 0; u < instance.q.size(); ++u)
      off += instance.q[u] == 0 ? M.back()[u] : 0;
    CHECK(off == result.off_curve);
    REQUIRE(result.snapshots.size() == 3);
    CHECK(result.snapshots[0].counts == M[1]);
    CHECK(result.snapshots[1].counts == M[result.t_out]);
    CHECK(result.snapshots[2].counts == M.back());
  }
}

TEST_CASE("simulation: the sweep prepares every case first", "[mc][simulation]") {
  const SimulationSetup setup = small_setup(1000);
  std::size_t calls = 0;
  const auto results = run_sweep(9, 10, {"C2", "C3"}, setup, 10,
                                 [&](std::size_t done, std::size_t total, int, const std::string&) {
                                   CHECK(done == calls++);
                                   CHECK(total == 4);
                                 });
  CHECK(calls == 4);
  REQUIRE(results.size() == 4);
  CHECK(results[0].m == 9);
  CHECK(results[0].curve == "C2");
  CHECK(results[3].m == 10);
  CHECK(results[3].curve == "C3");
  CHECK(results[0].snapshots.empty());
  CHECK(results[2].snapshots.size() == 3);
  CHECK(results[2].t_out == 67); // 1000 robots, m = 10, C2: `tioa-check simulate` pins it too
  CHECK(results[2].t_stab == 67);

  // C3's default radii do not fit m = 8 (a region meets both circles): reported before any run.
  calls = 0;
  CHECK_THROWS_WITH(run_sweep(8, 10, {"C3"}, setup, std::nullopt,
                              [&](std::size_t, std::size_t, int, const std::string&) { ++calls; }),
                    Catch::StartsWith("C3 on m = 8: "));
  CHECK(calls == 0);
  CHECK_THROWS_WITH(prepare_case(10, "C4", setup), Catch::Contains("choose C1, C2 or C3"));
  CHECK_THROWS_AS(run_sweep(11, 10, {"C1"}, setup), std::invalid_argument);
  SimulationSetup tiny_sigma = setup;
  tiny_sigma.sigma = Rational(1, 10'000'000);
  CHECK_THROWS_WITH(prepare_case(10, "C1", tiny_sigma), Catch::Contains("take a larger sigma"));

  SimulationSetup short_runs = setup;
  short_runs.max_rounds = 10;
  CHECK_THROWS_WITH(run_sweep(10, 10, {"C2"}, short_runs),
                    Catch::StartsWith("C2 on m = 10: no fixed point within 10 rounds"));
}

TEST_CASE("simulation: the claim about C2, at its threshold", "[mc][simulation]") {
  auto row = [](int m, const char* curve, std::size_t t_out, std::size_t t_stab) {
    SimulationResult r;
    r.m = m;
    r.curve = curve;
    r.t_out = t_out;
    r.t_stab = t_stab;
    return r;
  };
  CHECK_FALSE(check_dominance({row(10, "C1", 0, 5)}).has_value());

  // 9 of 10 is dominated (exactly at 9/10), 8 of 10 is not; T_stab = 0 counts as dominated.
  auto check = check_dominance({row(10, "C2", 9, 10), row(11, "C1", 0, 7), row(12, "C2", 0, 0)});
  REQUIRE(check.has_value());
  CHECK(check->holds);
  REQUIRE(check->rows.size() == 2);
  CHECK(check->rows[0].share == Approx(0.9));
  CHECK(check->rows[1].share == 1.0);
  CHECK(check->least_share == Approx(0.9));

  check = check_dominance({row(10, "C2", 9, 10), row(11, "C2", 8, 10)});
  REQUIRE(check.has_value());
  CHECK_FALSE(check->holds);
  CHECK_FALSE(check->rows[1].dominated);
  CHECK(check->least_share == Approx(0.8));
  CHECK(check_dominance({row(11, "C2", 8, 10)}, "C2", Rational(4, 5))->holds);
}

TEST_CASE("simulation: the CSV and the SVG figures", "[mc][simulation]") {
  const SimulationSetup setup = small_setup(1000);
  const auto results = run_sweep(9, 10, {"C1", "C2", "C3"}, setup, 10);
  const std::string csv = simulation_csv(results);
  CHECK(csv.rfind("m,curve,robots,T_out,T_stab,rounds,seconds\n", 0) == 0);
  CHECK(csv.find("\n10,C2,1000,67,67,68,") != std::string::npos);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 7);

  // Fig. 9: well-formed, an <svg> root, two lines (T_out, T_stab) and 2·2 markers per curve.
  const std::string fig9 = fig9_svg(results, "subtitle with <, > & \"quotes\"");
  const auto tree9 = parse_xml(fig9);
  REQUIRE(tree9.count("svg") == 1);
  CHECK(count_elements(tree9, "polyline") == 6);
  CHECK(count_elements(tree9, "circle") == 3 * 2 + 3); // T_stab points + legend
  CHECK(fig9.find("subtitle with &lt;, &gt; &amp; &quot;quotes&quot;") != std::string::npos);
  for (const char* label : {"C1  T_stab", "C2  T_out", "C3  T_stab", "rounds", ">10</text>"})
    CHECK(fig9.find(label) != std::string::npos);

  // Fig. 8: three panels of 10×10 cells.
  const SimulationResult& c2 = results[4];
  REQUIRE(c2.m == 10);
  REQUIRE(c2.curve == "C2");
  const std::string fig8 = fig8_svg(c2, "subtitle");
  const auto tree8 = parse_xml(fig8);
  REQUIRE(tree8.count("svg") == 1);
  CHECK(count_elements(tree8, "rect") > 3 * 100);
  for (const char* label : {"after round 1 (M_1)", "at T_out = 67 (M_67)", "at T_stab = 67",
                            "on the curve 0, off 1", "target: robots"})
    CHECK(fig8.find(label) != std::string::npos);
  CHECK_THROWS_AS(fig8_svg(results[0], ""), std::invalid_argument); // no snapshots at m = 9

  // The parser does reject what is not well-formed.
  CHECK_THROWS(parse_xml("<svg><rect></svg>"));
}
