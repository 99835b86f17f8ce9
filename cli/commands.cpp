#include "cli/commands.hpp"

#include <iostream>

#include "checker/interrupt.hpp"
#include "cli/exit_status.hpp"
#include "cli/model_run.hpp"
#include "cli/output.hpp"
#include "cli/render_html.hpp"
#include "cli/report_junit.hpp"
#include "cli/report_text.hpp"
#include "tioa/operators.hpp"

namespace cli {

namespace {

struct Built {
  const catalogue::ModelDefinition* definition;
  catalogue::ParamValues values;
  catalogue::ModelInstance instance;
};

Built build(const catalogue::Catalogue& models, const ModelRequest& request) {
  const catalogue::ModelDefinition& definition = models.find(request.model);
  catalogue::ParamValues values = catalogue::resolve_params(definition, request.param_settings);
  catalogue::ModelInstance instance = definition.build(values);
  return {&definition, std::move(values), std::move(instance)};
}

ModelRun start_run(const Built& built, const tioa::Automaton& system) {
  ModelRun run;
  run.model = built.definition->name;
  run.params = ordered_params(*built.definition, built.values);
  run.variant = catalogue::variant_name(*built.definition, built.values);
  run.quantum = built.instance.quantum;
  run.layout = system.layout();
  return run;
}

// Prints the report the settings ask for, writes the JUnit file and the HTML page, returns
// the exit code.
int report(const ModelRun& run, const catalogue::Picture& picture, const RunSettings& settings,
           std::optional<std::ofstream>& junit, std::optional<std::ofstream>& html) {
  if (settings.json)
    print_json(run_json(run, settings.trace != TraceMode::none));
  else
    print_text_report(std::cout, run, settings.trace);
  if (junit) {
    write_junit(*junit, {junit_suite(run, settings.trace)});
    junit->close();
    if (!*junit)
      throw catalogue::UsageError("cannot write the report file '" + settings.junit_path + "'");
  }
  if (html) {
    write_html(*html, run_json(run, true), picture);
    html->close();
    if (!*html)
      throw catalogue::UsageError("cannot write the HTML file '" + settings.html_path + "'");
  }
  return run.interrupted ? some_incomplete : exit_status(run.results);
}

// Runs the properties in order until a stop is requested (SIGINT, SIGTERM): the property
// that was running when it came reports what it covered, as incomplete; the rest do not run.
void run_properties(ModelRun& run, const tioa::Automaton& system,
                    const std::vector<const checker::Property*>& properties,
                    const checker::ExploreOptions& options) {
  for (std::size_t i = 0; i < properties.size(); ++i) {
    run.results.push_back(checker::run_property(system, *properties[i], options));
    if (checker::interrupted()) {
      run.interrupted = true;
      for (std::size_t later = i + 1; later < properties.size(); ++later)
        run.not_run.push_back(properties[later]->name);
      return;
    }
  }
}

} // namespace

int command_check(const catalogue::Catalogue& models, const ModelRequest& request,
                  const RunSettings& settings) {
  const Built built = build(models, request);
  const auto properties = select_properties(built.instance, request.model, request.properties);
  if (settings.store == checker::StoreKind::fingerprint)
    for (const checker::Property* property : properties)
      if (!checker::runs_on_fingerprint_store(*property))
        throw catalogue::UsageError(
            "--store fingerprint: property '" + property->name + "' of model '" + request.model +
            "' is a " + checker::to_string(property->kind) +
            " property; only invariants and deadlock / time-lock checks run on the fingerprint "
            "store (the others read states or edges after the search): use --store exact");
  auto junit = open_report_file(settings.junit_path);
  auto html = open_report_file(settings.html_path);
  ModelRun run = start_run(built, built.instance.system);
  run_properties(run, built.instance.system, properties, explore_options(settings));
  return report(run, built.definition->picture, settings, junit, html);
}

int command_explore(const catalogue::Catalogue& models, const ModelRequest& request,
                    const std::string& from, const RunSettings& settings) {
  if (from != "arbitrary" && from != "start")
    throw catalogue::UsageError("--from must be 'arbitrary' or 'start', not '" + from + "'");
  const Built built = build(models, request);
  std::vector<const checker::Property*> properties;
  for (const checker::Property* p :
       select_properties(built.instance, request.model, request.properties)) {
    if (p->kind == checker::PropertyKind::invariant)
      properties.push_back(p);
    else if (!request.properties.empty())
      throw catalogue::UsageError("explore checks invariants only: property '" + p->name +
                                  "' of model '" + request.model + "' is a " +
                                  checker::to_string(p->kind) + " property (use check)");
  }
  const tioa::Automaton system =
      from == "arbitrary" ? tioa::U(built.instance.system) : built.instance.system;
  checker::Property no_deadlock;
  no_deadlock.kind = checker::PropertyKind::deadlock;
  no_deadlock.predicate = built.instance.ended;
  no_deadlock.predicate_name = built.instance.ended_name;
  if (system.timed()) {
    no_deadlock.name = "no-timelock";
    no_deadlock.description = "no reachable state where neither an action nor a tick is possible";
  } else {
    no_deadlock.name = "no-deadlock";
    no_deadlock.description = "no reachable state where no action is enabled";
  }

  auto junit = open_report_file(settings.junit_path);
  auto html = open_report_file(settings.html_path);
  ModelRun run = start_run(built, system);
  run.from = from;
  const checker::ExploreOptions options = explore_options(settings);
  try {
    std::vector<const checker::Property*> all = properties;
    all.push_back(&no_deadlock);
    run_properties(run, system, all, options);
  } catch (const tioa::ModelError& e) {
    // Some models are defined only on the states they reach (mc-round's counts must add
    // up): a step from an arbitrary valuation leaves their domains. Say which, in one line.
    if (from != "arbitrary")
      throw;
    throw catalogue::UsageError("model '" + request.model +
                                "' is not defined on arbitrary states (a step from one gives: " +
                                e.what() + "); explore it with --from start");
  }
  return report(run, built.definition->picture, settings, junit, html);
}

} // namespace cli
