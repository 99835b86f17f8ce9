// Parameters of kind `choice` (catalogue/registry.hpp) and the parameters of mc-round that
// choose what its lemma properties check: curve, family (standard or given), samples, seed.
#include <catch2/catch.hpp>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"

using catalogue::ParamValue;
using checker::Verdict;

namespace {

std::string usage_error(const std::vector<std::string>& settings) {
  try {
    catalogue::resolve_params(catalogue::builtin_models().find("mc-round"), settings);
  } catch (const catalogue::UsageError& e) {
    return e.what();
  }
  return "<no UsageError>";
}

// One property of mc-round built with the settings, run on `threads` threads.
checker::PropertyResult run(const std::string& property, const std::vector<std::string>& settings,
                            unsigned threads = 1) {
  const auto& def = catalogue::builtin_models().find("mc-round");
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, settings));
  checker::ExploreOptions options;
  options.threads = threads;
  for (const auto& p : m.properties)
    if (p.name == property)
      return checker::run_property(m.system, p, options);
  FAIL("no property " << property);
  return {};
}

std::string figure(const checker::PropertyResult& r, const std::string& name) {
  for (const auto& [key, value] : r.figures)
    if (key == name)
      return value;
  return "<no figure " + name + ">";
}

} // namespace

TEST_CASE("choice parameters: a name from a list, kept as the name", "[models][registry][params]") {
  const ParamValue line = ParamValue::choice("line");
  CHECK(line.is_choice());
  CHECK(line.text() == "line");
  CHECK_FALSE(line.whole());
  CHECK(line == ParamValue::choice("line"));
  CHECK(line != ParamValue::choice("ring"));
  CHECK(line != ParamValue(0));
  CHECK_THROWS_AS(line.integer(), std::logic_error);
  CHECK_THROWS_AS(line.rational(), std::logic_error);
  CHECK_FALSE(ParamValue(3).is_choice());

  const auto& def = catalogue::builtin_models().find("mc-round");
  const catalogue::ParamValues defaults = catalogue::resolve_params(def, {});
  CHECK(defaults.at("curve") == ParamValue::choice("line"));
  CHECK(defaults.at("family") == ParamValue::choice("standard"));
  CHECK(defaults.at("samples") == 0);
  CHECK(defaults.at("seed") == 1);
  const catalogue::ParamValues set =
      catalogue::resolve_params(def, {"curve=hub-3", "family=given"});
  CHECK(set.at("curve").text() == "hub-3");
  CHECK(set.at("family").text() == "given");

  const auto family =
      std::find_if(def.params.begin(), def.params.end(),
                   [](const catalogue::ParamSpec& p) { return p.name == "family"; });
  REQUIRE(family != def.params.end());
  CHECK(family->kind == catalogue::ParamKind::choice);
  CHECK(family->choices == std::vector<std::string>{"standard", "given"});
  CHECK(family->range() == "{standard, given}");
  CHECK(std::string(catalogue::to_string(family->kind)) == "choice");
}

TEST_CASE("choice parameters: an unknown name is one line listing the choices",
          "[models][registry][params]") {
  CHECK(usage_error({"curve=zigzag"}) == "parameter curve: 'zigzag' is not one of none, point, "
                                         "line, L, ring, all, line-1-3, checker-1-3, hub-3");
  CHECK(usage_error({"family=Given"}) == "parameter family: 'Given' is not one of standard, given");
  CHECK(usage_error({"curve="}) ==
        "parameter curve: '' is not one of none, point, line, L, ring, all, line-1-3, "
        "checker-1-3, hub-3");
  // The old integer patterns are gone.
  CHECK(usage_error({"curve=2"}).rfind("parameter curve: '2' is not one of ", 0) == 0);
  CHECK(usage_error({"samples=-1"}) == "parameter samples = -1 is out of range 0..100000");
}

TEST_CASE("mc-round: family=given checks exactly the family the parameters name",
          "[mc][round][lemma-6.5]") {
  const checker::PropertyResult r =
      run("lemma-6.5", {"m=2", "nbh=8", "n=3", "curve=point", "k=1", "rho2=1/2", "family=given"});
  CHECK(r.verdict == Verdict::holds);
  // 4^4 = 256 configurations of counts 0..3, one per orbit of the 2 symmetries fixing the
  // point (0,0) (the identity and the transpose): 160 runs, 96 skipped.
  CHECK(r.states == 160);
  CHECK(r.edges == 136);
  CHECK(figure(r, "settings") == "1");
  CHECK_THAT(figure(r, "covered"),
             Catch::StartsWith("m x m grids, m in {2 (counts 0..3)}; neighbourhood 8; curves "
                               "{point} (q per region in units of sigma); k in {1}; rho2 in "
                               "{1/2}; every configuration"));
  CHECK_THAT(figure(r, "covered"),
             Catch::EndsWith("; 160 instances run to the fixed point in the default order, 96 "
                             "symmetric duplicates skipped"));
}

TEST_CASE("mc-round: family=standard and family=given differ, and `covered` says how",
          "[mc][round][lemma-6.1]") {
  const std::vector<std::string> given{"m=1", "nbh=4",    "n=6",         "curve=point",
                                       "k=2", "rho2=1/2", "family=given"};
  std::vector<std::string> standard = given;
  standard.back() = "family=standard";
  const checker::PropertyResult one = run("lemma-6.1", given);
  const checker::PropertyResult all = run("lemma-6.1", standard);
  CHECK(one.verdict == Verdict::holds);
  CHECK(all.verdict == Verdict::holds);
  CHECK(one.states == 7); // counts 0..6 on one region
  // 1×1 with counts 0..10; the 9 curves are 3 up to symmetry; 3 k, 4 rho2: 36 settings.
  CHECK(all.states == 36 * 11);
  CHECK(figure(one, "settings") == "1");
  CHECK(figure(all, "settings") == "36");
  CHECK_THAT(figure(one, "covered"),
             Catch::StartsWith("m x m grids, m in {1 (counts 0..6)}; neighbourhood 4; curves "
                               "{point} (q per region in units of sigma); k in {2}; rho2 in "
                               "{1/2}; "));
  CHECK_THAT(figure(all, "covered"),
             Catch::StartsWith("m x m grids, m in {1 (counts 0..10)}; neighbourhood 4; curves "
                               "{none, point, line, L, ring, all, line-1-3, checker-1-3, "
                               "hub-3} (q per region in units of sigma); k in {1, 2, 3}; rho2 "
                               "in {1/2, 9/10, 1/10, 2/3}; "));
}

TEST_CASE("mc-round: family=given re-runs conference Lemma 2(2)'s counterexample on its own "
          "family",
          "[mc][round][lemma-6.4]") {
  // proofs/README.md: 2×2, the curve along the bottom row (line on 2×2), k = 1, rho2 = 1/2,
  // counts 0 2 / 2 1 (5 robots).
  const std::vector<std::string> given{"m=2",      "nbh=4", "n=2",         "curve=line",
                                       "rho2=1/2", "k=1",   "family=given"};
  const checker::PropertyResult r = run("lemma-6.4", given);
  CHECK(r.verdict == Verdict::violated);
  CHECK_THAT(r.message, Catch::Contains("smallest counterexample: 5 robots, m = 2, claim L2(2)"));
  CHECK_THAT(figure(r, "covered"), Catch::StartsWith("m x m grids, m in {2 (counts 0..2)}; "
                                                     "neighbourhood 4; curves {line}"));
  // With at most one robot per region there are too few robots for it.
  std::vector<std::string> fewer = given;
  fewer[2] = "n=1";
  CHECK(run("lemma-6.4", fewer).verdict == Verdict::holds);
}

TEST_CASE("mc-round: samples > 0 runs the seeded random search on every lemma property",
          "[mc][round][search]") {
  const auto& def = catalogue::builtin_models().find("mc-round");
  for (const auto& [name, description] : def.properties) {
    // Lemma 6.8 has no population to sample: samples sets its random starts (below).
    if (name.rfind("lemma-", 0) != 0 || name == "lemma-6.8")
      continue;
    INFO("property " << name);
    const checker::PropertyResult r =
        run(name, {"m=2", "nbh=8", "samples=3", "seed=7", "search_m=5"});
    CHECK(r.verdict != Verdict::holds);
    CHECK(r.states == 3);
    CHECK_THAT(figure(r, "covered"), Catch::StartsWith("random search, seed 7, 3 samples: m in "
                                                       "2..5, neighbourhood 8, a third of the "
                                                       "samples a random grid path"));
  }
}

TEST_CASE("mc-round: lemma-6.8 takes rho1 from family=given and its random starts from samples",
          "[mc][round][lemma-6.8]") {
  const checker::PropertyResult r =
      run("lemma-6.8", {"m=2", "family=given", "rho1=1/3", "samples=3", "seed=7"});
  CHECK(r.verdict == Verdict::holds);
  CHECK_THAT(figure(r, "covered"), Catch::Contains("rho1 in {1/3}"));
  CHECK_THAT(figure(r, "covered"), Catch::Contains("3 seeded random starts"));
  CHECK_THAT(figure(r, "covered"), Catch::Contains("seed 7"));
}

TEST_CASE("mc-round: theorem-6.9 narrows its positional family with family=given",
          "[mc][round][theorem-6.9]") {
  const checker::PropertyResult r =
      run("theorem-6.9", {"m=1", "nbh=4", "family=given", "n=2", "k=1", "rho1=1/2", "rho2=1/2"});
  // One region: no neighbour to send to, so the assignment is fixed at once either way.
  CHECK(r.verdict == Verdict::holds);
  CHECK_THAT(figure(r, "covered (positions)"),
             Catch::StartsWith("m x m grids of side 1, m in {1 (eastward, westward, L)}"));
  CHECK_THAT(figure(r, "covered (positions)"), Catch::Contains("0..2 robots per region"));
}

TEST_CASE("mc-round: the fixed-point search holds on N samples, the same for every thread "
          "count",
          "[mc][round][search][lemma-6.5]") {
  const std::vector<std::string> settings{"m=3", "nbh=8", "samples=20"};
  const checker::PropertyResult one = run("lemma-6.5", settings, 1);
  CHECK(one.verdict == Verdict::incomplete);
  CHECK(one.message.rfind("holds on 20 samples (a random search, not a proof); ", 0) == 0);
  const checker::PropertyResult two = run("lemma-6.5", settings, 2);
  CHECK(two.message == one.message);
  CHECK(two.figures == one.figures);
  // family=given: this curve, k and rho2 on the grid m only.
  const checker::PropertyResult given =
      run("lemma-6.5", {"m=3", "nbh=8", "samples=5", "family=given", "curve=hub-3", "k=2"});
  CHECK_THAT(figure(given, "covered"),
             Catch::StartsWith("random search, seed 1, 5 samples: m in 3..3, neighbourhood 8, "
                               "curves {hub-3}, k in {2}, rho2 in {9/10}"));
}

TEST_CASE("mc-round: the registered model builds and its suite entries hold", "[mc][round]") {
  const auto& def = catalogue::builtin_models().find("mc-round");
  const auto values = catalogue::resolve_params(def, {"rho2=1/2", "nbh=4"});
  CHECK(values.at("rho2").text() == "1/2");
  CHECK_THROWS_WITH(catalogue::resolve_params(def, {"rho2=1"}),
                    "parameter rho2 = 1 is out of range (0, 1)");
  CHECK_THROWS_WITH(catalogue::resolve_params(def, {"rho2=x"}),
                    Catch::Contains("is not a rational number"));
  CHECK_THROWS_WITH(catalogue::resolve_params(def, {"nbh=5"}),
                    "model 'mc-round': nbh must be 4 or 8, not 5");
}
