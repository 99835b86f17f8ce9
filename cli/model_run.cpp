#include "cli/model_run.hpp"

#include <algorithm>

namespace cli {

BuiltModel build_model(const catalogue::Catalogue& models, const ModelRequest& request) {
  const catalogue::ModelDefinition& definition = models.find(request.model);
  catalogue::ParamValues values = catalogue::resolve_params(definition, request.param_settings);
  catalogue::ModelInstance instance = definition.build(values);
  return {&definition, std::move(values), std::move(instance)};
}

ModelRun start_run(const BuiltModel& built, const tioa::Automaton& system) {
  ModelRun run;
  run.model = built.definition->name;
  run.params = ordered_params(*built.definition, built.values);
  run.variant = catalogue::variant_name(*built.definition, built.values);
  run.quantum = built.instance.quantum;
  run.layout = system.layout();
  return run;
}

OrderedParams ordered_params(const catalogue::ModelDefinition& model,
                             const catalogue::ParamValues& values) {
  OrderedParams out;
  for (const auto& spec : model.params)
    if (const auto it = values.find(spec.name);
        it != values.end() && catalogue::shown_param(model, spec, values))
      out.emplace_back(spec.name, it->second);
  return out;
}

std::vector<std::string> param_settings(const catalogue::ParamValues& values) {
  std::vector<std::string> settings;
  for (const auto& [name, value] : values)
    settings.push_back(name + "=" + value.text());
  return settings;
}

checker::ExploreOptions explore_options(const RunSettings& settings) {
  checker::ExploreOptions options;
  options.limits = settings.limits;
  options.threads = settings.threads;
  options.por = settings.por;
  options.por_stabilisation = settings.por_stabilisation;
  options.store = settings.store;
  options.progress = true; // drawn only on a terminal, and only for runs longer than 1 s
  return options;
}

std::vector<const checker::Property*> select_properties(const catalogue::ModelInstance& instance,
                                                        const std::string& model,
                                                        const std::vector<std::string>& names) {
  std::vector<const checker::Property*> selected;
  if (names.empty()) {
    for (const auto& p : instance.properties)
      selected.push_back(&p);
    return selected;
  }
  for (const auto& name : names) {
    const auto it = std::find_if(instance.properties.begin(), instance.properties.end(),
                                 [&](const checker::Property& p) { return p.name == name; });
    if (it == instance.properties.end()) {
      std::string known;
      for (const auto& p : instance.properties)
        known += (known.empty() ? "" : ", ") + p.name;
      throw catalogue::UsageError("model '" + model + "' has no property '" + name +
                                  "' (it has: " + known + ")");
    }
    if (std::find(selected.begin(), selected.end(), &*it) == selected.end())
      selected.push_back(&*it);
  }
  return selected;
}

} // namespace cli
