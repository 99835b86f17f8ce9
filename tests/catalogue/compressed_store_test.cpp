// The compressed store (checker/state_tree.hpp) gives the exact store's results (same_result.hpp:
// verdict, counts, message, trace) for every property of a built-in model, with one and two
// threads, the partial-order reduction on where the model has it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "checker/property.hpp"
#include "tests/catalogue/same_result.hpp"

namespace {

// Which properties of an instance to compare.
enum class Which { fingerprint_store, the_others };

// Runs the properties of the instance that the fingerprint store accepts too (invariants,
// deadlock checks, the custom checks that say so), or the others (which read the stored
// states or edges after the search); returns how many.
int same_as_exact(const std::string& model, const std::vector<std::string>& settings, bool por,
                  Which which = Which::fingerprint_store,
                  const std::vector<std::string>& only = {}) {
  const auto& definition = catalogue::builtin_models().find(model);
  const auto instance = definition.build(catalogue::resolve_params(definition, settings));
  int compared = 0;
  for (const checker::Property& property : instance.properties) {
    if (checker::runs_on_fingerprint_store(property) != (which == Which::fingerprint_store))
      continue;
    if (!only.empty() && std::find(only.begin(), only.end(), property.name) == only.end())
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

TEST_CASE("compressed store: the checks that read states or edges after the search give the "
          "exact store's results on the built-in models",
          "[catalogue][compressed]") {
  // Stabilisation, legal sets, closure, transitivity, R(A) and the custom checks that read
  // the stored states (StateReader), on small instances.
  CHECK(same_as_exact("token-ring", {"N=4", "K=3"}, false, Which::the_others) >= 3);
  CHECK(same_as_exact("path-reservation", {"scenario=late-joiner"}, true, Which::the_others) >= 2);
  CHECK(same_as_exact("vn-layer", {"start=corner"}, true, Which::the_others) >= 6);
  CHECK(same_as_exact("vlayer-mc", {"cols=1", "samples=20"}, false, Which::the_others,
                      {"l1mc-closure", "reset-in-l1mc", "lmc-closure", "lemma-7.3", "lemma-7.4",
                       "theorem-7.5"}) == 6);
}
