// The compressed store (checker/state_tree.hpp) gives the exact store's results (same_result.hpp:
// verdict, counts, message, trace) for every property of a built-in model that runs on it,
// with one and two threads, the partial-order reduction on where the model has it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "checker/property.hpp"
#include "tests/catalogue/same_result.hpp"

namespace {

// Runs every property of the instance that the compressed store accepts; returns how many.
int same_as_exact(const std::string& model, const std::vector<std::string>& settings, bool por) {
  const auto& definition = catalogue::builtin_models().find(model);
  const auto instance = definition.build(catalogue::resolve_params(definition, settings));
  int compared = 0;
  for (const checker::Property& property : instance.properties) {
    if (!checker::runs_on_fingerprint_store(property))
      continue;
    INFO(model << " " << property.name);
    checker::ExploreOptions exact;
    exact.por = por;
    const checker::PropertyResult expected =
        checker::run_property(instance.system, property, exact);
    for (unsigned threads : {1u, 2u}) {
      checker::ExploreOptions compressed = exact;
      compressed.store = checker::StoreKind::compressed;
      compressed.threads = threads;
      const checker::PropertyResult r =
          checker::run_property(instance.system, property, compressed);
      CHECK(r.store == "compressed");
      catalogue_test::check_same_result(r, expected);
    }
    ++compared;
  }
  return compared;
}

} // namespace

TEST_CASE("compressed store: the exact store's results on every built-in model",
          "[catalogue][compressed]") {
  // Each model with its invariants, deadlock / time-lock checks and the custom checks that
  // run on it; small instances (the larger ones are in bench/README.md).
  CHECK(same_as_exact("path-reservation", {"scenario=late-joiner"}, false) == 3);
  CHECK(same_as_exact("path-reservation", {"scenario=range-edge"}, true) == 3);
  CHECK(same_as_exact("vlayer-mc", {"cols=3"}, true) >= 1);
  CHECK(same_as_exact("vlayer-mc", {}, false) >= 1);
  CHECK(same_as_exact("vn-layer", {"start=corner"}, true) >= 1);
  CHECK(same_as_exact("vn-emulation", {"fails=0"}, false) == 5);
  CHECK(same_as_exact("vn-emulation", {"zones=2", "fails=0", "moves=0", "rp2=9"}, false) == 5);
  CHECK(same_as_exact("fischer", {"N=3"}, false) >= 1);
  CHECK(same_as_exact("token-ring", {"N=4", "K=3"}, false) >= 1);
}
