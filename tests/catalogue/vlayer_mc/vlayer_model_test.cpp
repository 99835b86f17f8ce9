// The model `vlayer-mc`: parameters and the state count of the smallest instance. Not yet in
// catalogue::all_models(): tests/models/registry_test.cpp pins the list of known models, so
// registering it needs that test updated with it.
#include <catch2/catch.hpp>

#include "catalogue/registry.hpp"
#include "catalogue/vlayer_mc.hpp"
#include "checker/property.hpp"

TEST_CASE("vlayer-mc: bad parameters are one-line usage errors", "[vlayer]") {
  const catalogue::ModelDefinition def = catalogue::vlayer_mc_definition();
  CHECK_THROWS_AS(catalogue::resolve_params(def, {"nbh=5"}), catalogue::UsageError);
  CHECK_THROWS_AS(catalogue::resolve_params(def, {"b=3"}), catalogue::UsageError);
  // The target phase e + 2d + 2ε = 2 must fall inside the round.
  CHECK_THROWS_AS(catalogue::resolve_params(def, {"delta=2"}), catalogue::UsageError);
  CHECK_THROWS_AS(catalogue::resolve_params(def, {"rho2=1"}), catalogue::UsageError);
  const auto values = catalogue::resolve_params(def, {"rows=2", "cols=2", "nbh=8", "robots=3"});
  const vlayer_mc::VlConfig c = catalogue::vlayer_config(values);
  CHECK(c.lattice().regions() == 4);
  CHECK(c.nbh == mc::Neighbourhood::eight);
}

// 1×2 grid, b = 2, one robot from (0, 2), δ = 6, d = 1, e = ε = 0, ε_sample = 1, d_r = 1,
// v_max = 4, k = 1, ρ1 = 1/2, ρ2 = 9/10, no robot or VSA failures.
TEST_CASE("vlayer-mc: exact state count of the smallest instance", "[vlayer]") {
  const catalogue::ModelDefinition def = catalogue::vlayer_mc_definition();
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, {}));
  const checker::PropertyResult r = checker::run_property(m.system, m.properties.at(0), {});
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(r.states == 2'706);
  CHECK(r.edges == 8'993);
}

// VSA failures anywhere (VW's fail_u/restart_u): these were the counts before finding F2
// was fixed, when Fail(VN_u)'s inputs stayed open with vsa_faults=0.
TEST_CASE("vlayer-mc: state count with VSA failures anywhere", "[vlayer]") {
  const catalogue::ModelDefinition def = catalogue::vlayer_mc_definition();
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, {"vsa_faults=1"}));
  const checker::PropertyResult r = checker::run_property(m.system, m.properties.at(0), {});
  CHECK(r.verdict == checker::Verdict::holds);
  CHECK(r.states == 205'980);
  CHECK(r.edges == 1'309'564);
}
