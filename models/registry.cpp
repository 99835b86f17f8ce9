#include "models/registry.hpp"

#include <charconv>

#include "models/fischer/fischer.hpp"
#include "models/token_ring/token_ring.hpp"

namespace models {

const std::vector<ModelDefinition>& all_models() {
  static const std::vector<ModelDefinition> models{token_ring_definition(), fischer_definition()};
  return models;
}

const ModelDefinition& find_model(const std::string& name) {
  for (const auto& m : all_models())
    if (m.name == name)
      return m;
  std::string known;
  for (const auto& m : all_models())
    known += (known.empty() ? "" : ", ") + m.name;
  throw UsageError("unknown model '" + name + "' (known: " + known + ")");
}

ParamValues resolve_params(const ModelDefinition& model, const std::vector<std::string>& settings) {
  ParamValues values;
  for (const auto& p : model.params)
    values[p.name] = p.default_value;
  for (const auto& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("parameter setting '" + setting + "' is not of the form name=value");
    const std::string name = setting.substr(0, eq), text = setting.substr(eq + 1);
    const ParamSpec* spec = nullptr;
    for (const auto& p : model.params)
      if (p.name == name)
        spec = &p;
    if (!spec) {
      std::string known;
      for (const auto& p : model.params)
        known += (known.empty() ? "" : ", ") + p.name;
      throw UsageError("model '" + model.name + "' has no parameter '" + name +
                       "' (it has: " + known + ")");
    }
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
      throw UsageError("parameter " + name + ": '" + text + "' is not a whole number");
    if (value < spec->lo || value > spec->hi)
      throw UsageError("parameter " + name + " = " + text + " is out of range " +
                       std::to_string(spec->lo) + ".." + std::to_string(spec->hi));
    values[name] = value;
  }
  if (model.check_params)
    if (auto why = model.check_params(values))
      throw UsageError("model '" + model.name + "': " + *why);
  return values;
}

} // namespace models
