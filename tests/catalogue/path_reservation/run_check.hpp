#pragma once
// Runs one property of `path-reservation` on a scenario, with any other parameters given
// as the command line would ("msg_rule=any-zone"), on two threads.

#include <stdexcept>
#include <string>
#include <vector>

#include "catalogue/builtin.hpp"
#include "catalogue/path_reservation.hpp"
#include "catalogue/registry.hpp"
#include "checker/property.hpp"

namespace path_reservation_test {

// Runs one property with the parameters as given ("scenario_file=..." in place of a
// scenario).
inline checker::PropertyResult run_with(const std::vector<std::string>& settings,
                                        const std::string& property) {
  const auto& definition = catalogue::builtin_models().find("path-reservation");
  const auto instance = definition.build(catalogue::resolve_params(definition, settings));
  for (const auto& p : instance.properties)
    if (p.name == property) {
      checker::ExploreOptions options;
      options.threads = 2;
      return checker::run_property(instance.system, p, options);
    }
  throw std::logic_error("test: no property " + property);
}

inline checker::PropertyResult run(const std::string& scenario, const std::string& property,
                                   std::vector<std::string> settings = {}) {
  settings.push_back("scenario=" + scenario);
  return run_with(settings, property);
}

} // namespace path_reservation_test
