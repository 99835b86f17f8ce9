#pragma once
// Running a `vlayer-mc` property by name with `name=value` settings, and reading its result's
// figures and notes: shared by the property tests of tests/models/vlayer_mc.

#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "catalogue/registry.hpp"
#include "catalogue/vlayer_mc.hpp"
#include "checker/property.hpp"

namespace vl_test {

struct PropertyRun {
  checker::PropertyResult result;
  tioa::Automaton system; // to replay the result's trace: its trace_system, else the model's
};

inline PropertyRun run_property(const std::string& property,
                                const std::vector<std::string>& settings) {
  const catalogue::ModelDefinition def = catalogue::vlayer_mc_definition();
  const catalogue::ModelInstance m = def.build(catalogue::resolve_params(def, settings));
  for (const auto& p : m.properties)
    if (p.name == property) {
      checker::PropertyResult r = checker::run_property(m.system, p, {});
      const tioa::Automaton system = r.trace_system ? *r.trace_system : m.system;
      return {std::move(r), system};
    }
  FAIL("no property " << property);
  return {{}, m.system};
}

// The figure called `name`, or "" when there is none.
inline std::string figure(const checker::PropertyResult& r, const std::string& name) {
  for (const auto& [key, value] : r.figures)
    if (key == name)
      return value;
  return "";
}

inline bool has_note(const checker::PropertyResult& r, const std::string& start) {
  for (const auto& note : r.notes)
    if (note.rfind(start, 0) == 0)
      return true;
  return false;
}

} // namespace vl_test
