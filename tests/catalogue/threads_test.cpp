// The same results for 1, 2 and 4 threads (same_result.hpp) on the built-in models the
// token ring and Fischer tests do not cover (theirs are in token_ring_test.cpp and
// fischer_test.cpp).
#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

#include "catalogue/builtin.hpp"
#include "catalogue/registry.hpp"
#include "checker/property.hpp"
#include "tests/catalogue/same_result.hpp"

namespace {

void same_for_every_thread_count(const std::string& model, const std::vector<std::string>& settings,
                                 const std::vector<std::string>& properties) {
  const auto& definition = catalogue::builtin_models().find(model);
  const auto instance = definition.build(catalogue::resolve_params(definition, settings));
  for (const std::string& name : properties) {
    INFO(model << " " << name);
    const checker::Property* spec = nullptr;
    for (const auto& p : instance.properties)
      if (p.name == name)
        spec = &p;
    REQUIRE(spec);
    std::optional<checker::PropertyResult> first;
    for (unsigned threads : {1u, 2u, 4u}) {
      checker::ExploreOptions options;
      options.threads = threads;
      const checker::PropertyResult r = checker::run_property(instance.system, *spec, options);
      if (!first) {
        first = r;
        continue;
      }
      catalogue_test::check_same_result(r, *first);
    }
  }
}

} // namespace

// The cycle scenario is small (2,475 states: one worker per level); the larger ones take
// seconds (bench/README.md).
TEST_CASE("path-reservation: the same results for 1, 2 and 4 threads",
          "[catalogue][path_reservation][threads]") {
  same_for_every_thread_count("path-reservation", {"scenario=cycle"},
                              {"mutual-exclusion", "integrity", "no-collision", "progress"});
}

TEST_CASE("vlayer-mc: the same results for 1, 2 and 4 threads", "[catalogue][vlayer_mc][threads]") {
  // 1x2: LMC's 38,311 classes; 1x3: 32,134 states (levels of a few thousand states at
  // most: the concurrent levels are tested on the peer models, checker/explorer_test.cpp).
  same_for_every_thread_count("vlayer-mc", {}, {"lmc-closure"});
  same_for_every_thread_count("vlayer-mc", {"cols=3"}, {"no-timelock", "l1mc-closure"});
}

TEST_CASE("mc-round: the same results for 1, 2 and 4 threads", "[catalogue][mc_round][threads]") {
  same_for_every_thread_count("mc-round", {"m=3", "n=2"}, {"fixpoint"}); // 3^9 configurations
}

TEST_CASE("vn-layer: the same results for 1, 2 and 4 threads", "[catalogue][vn_layer][threads]") {
  // 2x1 from every placement (105,854 states; round-closure's rounds 113,948), and from the
  // corner with delta = 12, where round-timing and round-closure find V1 with a trace.
  same_for_every_thread_count("vn-layer", {}, {"round-timing", "stabilisation", "round-closure"});
  same_for_every_thread_count("vn-layer", {"start=corner", "delta=12"},
                              {"round-timing", "round-closure"});
}

TEST_CASE("vn-emulation: the same results for 1, 2 and 4 threads",
          "[catalogue][vn_emulation][threads]") {
  // One zone, the defaults (120,790 states); F1's time-lock; two zones where VN -> VN is lost.
  same_for_every_thread_count("vn-emulation", {}, {"replica-consistency"});
  same_for_every_thread_count(
      "vn-emulation", {"start=cold", "messages=0", "fails=0", "restart=printed"}, {"no-timelock"});
  same_for_every_thread_count("vn-emulation", {"zones=2", "fails=0", "moves=0", "rp2=9"},
                              {"theorem-2"});
}
