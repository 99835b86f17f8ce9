#pragma once
// One model instance and the results of the properties run on it: what every report
// (text, JSON, JUnit) is made from.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "catalogue/registry.hpp"
#include "checker/property.hpp"
#include "cli/settings.hpp"
#include "tioa/variables.hpp"

namespace cli {

// Parameter values in the model's declaration order.
using OrderedParams = std::vector<std::pair<std::string, catalogue::ParamValue>>;

struct ModelRun {
  std::string model;
  OrderedParams params;
  // "paper", or the variant parameters set away from the paper's algorithm; "" when the
  // model declares no variant (catalogue::variant_name).
  std::string variant;
  std::string quantum;             // what one tick is; empty when the model is untimed
  std::string command = "explore"; // the command that ran: explore, walk (for the header)
  std::string from;                // explore, walk: "arbitrary" or "start"; empty otherwise
  std::string start;               // --start: the start predicate as given (empty: none)
  std::string invariant;           // --invariant: the invariant as given (empty: none)
  tioa::StateLayout layout;
  std::vector<checker::PropertyResult> results;
  // A stop was requested (SIGINT, SIGTERM) while the last result ran: it is incomplete, and
  // the properties named in not_run were not run.
  bool interrupted = false;
  std::vector<std::string> not_run;
};

// A model definition, its resolved parameters and the instance they build.
struct BuiltModel {
  const catalogue::ModelDefinition* definition;
  catalogue::ParamValues values;
  catalogue::ModelInstance instance;
};

// Resolves the request's parameters and builds the instance; throws UsageError.
BuiltModel build_model(const catalogue::Catalogue& models, const ModelRequest& request);

// A run of `built` on `system` (the instance's system, or U of it) with no results yet.
ModelRun start_run(const BuiltModel& built, const tioa::Automaton& system);

OrderedParams ordered_params(const catalogue::ModelDefinition& model,
                             const catalogue::ParamValues& values);

// "name=value" settings for resolve_params, from a suite entry's values.
std::vector<std::string> param_settings(const catalogue::ParamValues& values);

checker::ExploreOptions explore_options(const RunSettings& settings);

// The properties named in `names` (every property when empty), in the order asked, each
// once; a UsageError names an unknown one and lists the known ones.
std::vector<const checker::Property*> select_properties(const catalogue::ModelInstance& instance,
                                                        const std::string& model,
                                                        const std::vector<std::string>& names);

} // namespace cli
