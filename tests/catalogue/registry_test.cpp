// The model registry (catalogue/registry.hpp): every model builds, lists its properties
// consistently and gives the suite's expected verdicts; parameters are checked.
#include <catch2/catch.hpp>

#include <algorithm>

#include <set>
#include <stdexcept>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"

using catalogue::UsageError;
using checker::Verdict;

namespace {

// The message of the UsageError that resolve_params throws, or a marker when none.
std::string usage_error(const std::string& model, const std::vector<std::string>& settings) {
  try {
    catalogue::resolve_params(catalogue::builtin_models().find(model), settings);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "<no UsageError>";
}

} // namespace

TEST_CASE("registry: every model builds with its defaults and lists its properties",
          "[models][registry]") {
  const auto& all = catalogue::builtin_models().models();
  REQUIRE(all.size() >= 2);
  std::set<std::string> names;
  for (const auto& def : all) {
    INFO("model " << def.name);
    CHECK(names.insert(def.name).second); // names are unique
    CHECK_FALSE(def.description.empty());
    CHECK(&catalogue::builtin_models().find(def.name) == &def);
    for (const auto& p : def.params) {
      if (p.kind == catalogue::ParamKind::choice) {
        CHECK(std::count(p.choices.begin(), p.choices.end(), p.default_value.text()) == 1);
      } else if (p.kind == catalogue::ParamKind::text) {
        CHECK(p.default_value.is_text()); // any text is in range
      } else {
        CHECK(p.lo <= p.default_value);
        CHECK(p.default_value <= p.hi);
      }
      CHECK_FALSE(p.description.empty());
    }
    const catalogue::ParamValues defaults = catalogue::resolve_params(def, {});
    CHECK(defaults.size() == def.params.size());
    for (const auto& p : def.params)
      CHECK(defaults.at(p.name) == p.default_value);
    const catalogue::ModelInstance m = def.build(defaults);
    std::vector<std::string> listed, built;
    for (const auto& [name, description] : def.properties) {
      listed.push_back(name);
      CHECK_FALSE(description.empty());
    }
    for (const auto& p : m.properties)
      built.push_back(p.name);
    CHECK(listed == built);
    CHECK(std::set<std::string>(listed.begin(), listed.end()).size() == listed.size());
  }
  CHECK(names.count("token-ring") == 1);
  CHECK(names.count("fischer") == 1);
}

// Every entry's verdict, and every expected violation's counterexample, is checked by
// cli.suite (the whole suite through the CLI, once: tests/cli/suite_expected.py); here every
// entry builds and names a property of its instance.
TEST_CASE("registry: every suite entry builds and names a property of its instance",
          "[models][registry][suite]") {
  for (const auto& def : catalogue::builtin_models().models()) {
    CHECK_FALSE(def.suite.empty());
    for (const auto& entry : def.suite) {
      // The entry's values, on top of the defaults, go through the same checks as a user's.
      std::vector<std::string> settings;
      for (const auto& [name, value] : entry.params)
        settings.push_back(name + "=" + value.text());
      INFO("model " << def.name << ", property " << entry.property);
      const catalogue::ParamValues values = catalogue::resolve_params(def, settings);
      const catalogue::ModelInstance m = def.build(values);
      CHECK(std::any_of(m.properties.begin(), m.properties.end(),
                        [&](const checker::Property& p) { return p.name == entry.property; }));
    }
  }
}

TEST_CASE("registry: find names the known models when it fails", "[models][registry]") {
  try {
    catalogue::builtin_models().find("fisher");
    FAIL("no UsageError");
  } catch (const UsageError& e) {
    CHECK(std::string(e.what()) == "unknown model 'fisher' (known: token-ring, fischer, mc-round, "
                                   "vlayer-mc, vn-layer, vn-emulation, path-reservation)");
  }
}

TEST_CASE("resolve_params: defaults and overrides", "[models][registry][params]") {
  const auto& ring = catalogue::builtin_models().find("token-ring");
  CHECK(catalogue::resolve_params(ring, {}) == catalogue::ParamValues{{"N", 5}, {"K", 4}});
  CHECK(catalogue::resolve_params(ring, {"N=3"}) == catalogue::ParamValues{{"N", 3}, {"K", 4}});
  CHECK(catalogue::resolve_params(ring, {"K=2", "N=7"}) ==
        catalogue::ParamValues{{"N", 7}, {"K", 2}});
  // Two values for one parameter are refused, not the last one kept (issue 17).
  CHECK_THROWS_WITH(catalogue::resolve_params(ring, {"N=3", "N=4"}),
                    "parameter N is given twice (N=3 and N=4)");
  // The ends of each range are allowed.
  CHECK(catalogue::resolve_params(ring, {"N=2", "K=64"}).at("K") == 64);
  const auto& fischer = catalogue::builtin_models().find("fischer");
  CHECK(catalogue::resolve_params(fischer, {}) ==
        catalogue::ParamValues{{"N", 3}, {"A", 1}, {"B", 2}});
  CHECK(catalogue::resolve_params(fischer, {"A=0", "B=0"}) ==
        catalogue::ParamValues{{"N", 3}, {"A", 0}, {"B", 0}});
  CHECK(catalogue::resolve_params(fischer, {"B=-0"}).at("B") == 0);
}

TEST_CASE("resolve_params: bad settings are a UsageError with a clear message",
          "[models][registry][params]") {
  SECTION("unknown name") {
    CHECK(usage_error("token-ring", {"M=3"}) ==
          "model 'token-ring' has no parameter 'M' (it has: N, K)");
    CHECK(usage_error("fischer", {"n=3"}) ==
          "model 'fischer' has no parameter 'n' (it has: N, A, B)");
  }
  SECTION("not of the form name=value") {
    CHECK(usage_error("token-ring", {"N"}) ==
          "parameter setting 'N' is not of the form name=value");
    CHECK(usage_error("token-ring", {"=3"}) ==
          "parameter setting '=3' is not of the form name=value");
    CHECK(usage_error("token-ring", {""}) == "parameter setting '' is not of the form name=value");
  }
  SECTION("malformed value") {
    for (const std::string text : {"", "abc", "3.5", "3x", " 3", "3 ", "+3", "0x10", "1e2"})
      CHECK(usage_error("token-ring", {"N=" + text}) ==
            "parameter N: '" + text + "' is not a whole number");
    CHECK(usage_error("token-ring", {"N=99999999999999999999"}) ==
          "parameter N = 99999999999999999999 is out of range 2..20");
  }
  SECTION("out of range") {
    CHECK(usage_error("token-ring", {"N=1"}) == "parameter N = 1 is out of range 2..20");
    CHECK(usage_error("token-ring", {"N=21"}) == "parameter N = 21 is out of range 2..20");
    CHECK(usage_error("token-ring", {"K=-1"}) == "parameter K = -1 is out of range 2..64");
    CHECK(usage_error("fischer", {"N=13"}) == "parameter N = 13 is out of range 2..12");
    CHECK(usage_error("fischer", {"B=31"}) == "parameter B = 31 is out of range 0..30");
  }
  SECTION("values that do not fit together") {
    const std::string why = usage_error("token-ring", {"N=20", "K=64"});
    CHECK(why.rfind("model 'token-ring': K^N = ", 0) == 0);
    CHECK(why.find("more than the 2^32 the checker can store") != std::string::npos);
    CHECK(usage_error("token-ring", {"N=12", "K=6"}) == "<no UsageError>"); // 6^12 = 2.2e9
  }
  SECTION("the first bad setting is the one reported") {
    CHECK(usage_error("token-ring", {"N=3", "K=x", "M=1"}) ==
          "parameter K: 'x' is not a whole number");
  }
}

// Regression: the suite keys its built instances by parameter set; ParamValue's order once
// made every choice equal, so `scenario=head-on` reused the instance of `scenario=crossing`.
TEST_CASE("ParamValue: choices are ordered, so parameter sets can key a map",
          "[models][registry][params]") {
  const auto a = catalogue::ParamValue::choice("crossing"),
             b = catalogue::ParamValue::choice("head-on");
  CHECK(a < b);
  CHECK_FALSE(b < a);
  CHECK(catalogue::ParamValue(0) < a);
  CHECK(catalogue::ParamValue(1) > a);
  std::map<catalogue::ParamValues, int> keyed;
  keyed[{{"scenario", a}}] = 1;
  keyed[{{"scenario", b}}] = 2;
  CHECK(keyed.size() == 2);
}

TEST_CASE("Catalogue: add refuses a model without a name, without build, or named twice",
          "[models][registry]") {
  catalogue::Catalogue models;
  catalogue::ModelDefinition model;
  CHECK_THROWS_AS(models.add(model), std::invalid_argument);
  model.name = "m";
  CHECK_THROWS_AS(models.add(model), std::invalid_argument);
  model.build = [](const catalogue::ParamValues&) {
    return catalogue::ModelInstance{tioa::Automaton("m"), {}, ""};
  };
  models.add(model);
  CHECK_THROWS_AS(models.add(model), std::invalid_argument);
  CHECK(models.models().size() == 1);
  CHECK(&models.find("m") == &models.models().front());
  CHECK_THROWS_WITH(models.find("n"), "unknown model 'n' (known: m)");
}

TEST_CASE("builtin_models: vlayer-mc and path-reservation bring their pictures",
          "[models][registry]") {
  for (const auto& def : catalogue::builtin_models()) {
    INFO("model " << def.name);
    CHECK(static_cast<bool>(def.picture) ==
          (def.name == "vlayer-mc" || def.name == "path-reservation"));
  }
}

// Issue 15: a variant parameter's default is the paper's algorithm, and the name of the
// variant run lists those set away from it.
TEST_CASE("variant_name: paper by default, else the changes", "[models][registry][variant]") {
  const catalogue::Catalogue models = catalogue::builtin_models();
  const catalogue::ModelDefinition& vlayer = models.find("vlayer-mc");
  std::vector<std::string> variants;
  for (const auto& p : vlayer.params)
    if (p.variant)
      variants.push_back(p.name);
  CHECK(variants ==
        std::vector<std::string>{"cn_repair", "vn_repair", "filter_targets", "owned_ends"});
  CHECK(catalogue::variant_name(vlayer, catalogue::resolve_params(vlayer, {})) == "paper");
  CHECK(catalogue::variant_name(vlayer, catalogue::resolve_params(vlayer, {"rows=2"})) == "paper");
  CHECK(catalogue::variant_name(
            vlayer, catalogue::resolve_params(vlayer, {"filter_targets=1", "cn_repair=1"})) ==
        "cn_repair=1,filter_targets=1");
  const catalogue::ModelDefinition& paths = models.find("path-reservation");
  CHECK(catalogue::variant_name(
            paths, catalogue::resolve_params(paths, {"variant=release-before-reserve"})) ==
        "variant=release-before-reserve");
}
