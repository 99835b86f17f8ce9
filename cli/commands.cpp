#include "cli/commands.hpp"

#include <iostream>

#include "checker/interrupt.hpp"
#include "cli/counterexample_file.hpp"
#include "cli/exit_status.hpp"
#include "cli/model_run.hpp"
#include "cli/output.hpp"
#include "cli/render_html.hpp"
#include "cli/report_junit.hpp"
#include "cli/report_text.hpp"
#include "cli/run_system.hpp"
#include "cli/state_graph.hpp"
#include "cli/trace_file.hpp"
#include "tioa/operators.hpp"

namespace cli {

namespace {

// The report files a run writes, each opened before the run (a path that cannot be written
// is a usage error before anything runs).
struct ReportFiles {
  std::optional<std::ofstream> junit, html, trace_out, counterexample_out;
  explicit ReportFiles(const RunSettings& settings)
      : junit(open_report_file(settings.junit_path)), html(open_report_file(settings.html_path)),
        trace_out(open_report_file(settings.trace_out_path)),
        counterexample_out(open_report_file(settings.counterexample_out_path)) {}
};

// The properties a check or explore runs: those asked for (`chosen`), and the one given with
// --invariant (alone when no --prop asks for others). --start narrows the start states of
// the checks that explore the system; a check of its own (proofs/) builds its own systems,
// so the two do not go together.
std::vector<const checker::Property*>
with_given_invariant(std::vector<const checker::Property*> chosen,
                     const std::optional<checker::Property>& invariant, const ModelRequest& request,
                     const RunSettings& settings) {
  if (invariant && request.properties.empty())
    chosen.clear();
  if (invariant)
    chosen.push_back(&*invariant);
  if (!settings.start.empty())
    for (const checker::Property* p : chosen)
      if (p->kind == checker::PropertyKind::custom)
        throw catalogue::UsageError("--start: property '" + p->name + "' of model '" +
                                    request.model +
                                    "' is a check of its own, with its own start states; --start "
                                    "narrows the start states of invariants, legal sets, "
                                    "stabilisation and deadlock checks (choose them with --prop)");
  return chosen;
}

// Prints the report the settings ask for, writes the JUnit file, the HTML page and the
// trace file, returns the exit code.
int report(const ModelRun& run, const catalogue::ModelDefinition& definition,
           const RunSettings& settings, ReportFiles& files) {
  std::optional<std::ofstream>& junit = files.junit;
  std::optional<std::ofstream>& html = files.html;
  if (files.trace_out)
    write_trace_file(*files.trace_out, settings.trace_out_path, run);
  if (files.counterexample_out)
    write_counterexample_file(files.counterexample_out, settings.counterexample_out_path, run);
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
    write_html(*html, run_json(run, true), definition.picture, definition.explain);
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
  const BuiltModel built = build_model(models, request);
  const tioa::Automaton system = run_system(built, "start", settings.start);
  std::optional<checker::Property> invariant;
  if (!settings.invariant.empty())
    invariant = given_invariant(system.layout(), settings.invariant, built.instance);
  const auto properties =
      with_given_invariant(select_properties(built.instance, request.model, request.properties),
                           invariant, request, settings);
  if (settings.store == checker::StoreKind::fingerprint)
    for (const checker::Property* property : properties)
      if (!checker::runs_on_fingerprint_store(*property))
        throw catalogue::UsageError(
            "--store fingerprint: property '" + property->name + "' of model '" + request.model +
            "' is a " + checker::to_string(property->kind) +
            " property that reads states or edges after the search, which the fingerprint "
            "store does not keep (invariants, deadlock / time-lock checks and some custom "
            "checks run on it): use --store exact or --store compressed");
  ReportFiles files(settings);
  if (!settings.dot_path.empty())
    write_state_graph(system, settings.dot_path);
  ModelRun run = start_run(built, system);
  run.start = settings.start;
  run.invariant = settings.invariant;
  run_properties(run, system, properties, explore_options(settings));
  return report(run, *built.definition, settings, files);
}

int command_explore(const catalogue::Catalogue& models, const ModelRequest& request,
                    const std::string& from, const RunSettings& settings) {
  if (from != "arbitrary" && from != "start")
    throw catalogue::UsageError("--from must be 'arbitrary' or 'start', not '" + from + "'");
  const BuiltModel built = build_model(models, request);
  const tioa::Automaton system = run_system(built, from, settings.start);
  std::optional<checker::Property> invariant;
  if (!settings.invariant.empty())
    invariant = given_invariant(system.layout(), settings.invariant, built.instance);
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
  properties = with_given_invariant(properties, invariant, request, settings);
  checker::Property no_deadlock;
  no_deadlock.kind = checker::PropertyKind::deadlock;
  no_deadlock.predicate = built.instance.ended;
  no_deadlock.predicate_name = built.instance.ended_name;
  no_deadlock.beyond_bound = built.instance.beyond_bound;
  no_deadlock.bound_name = built.instance.bound_name;
  if (system.timed()) {
    no_deadlock.name = "no-timelock";
    no_deadlock.description = "no reachable state where neither an action nor a tick is possible";
  } else {
    no_deadlock.name = "no-deadlock";
    no_deadlock.description = "no reachable state where no action is enabled";
  }

  ReportFiles files(settings);
  if (!settings.dot_path.empty())
    write_state_graph(system, settings.dot_path);
  ModelRun run = start_run(built, system);
  run.from = from;
  run.start = settings.start;
  run.invariant = settings.invariant;
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
  return report(run, *built.definition, settings, files);
}

} // namespace cli
