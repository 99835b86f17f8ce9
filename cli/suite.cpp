// The suite: every SuiteEntry of every model, checked against its expected verdict. This
// is the run CI pipelines call after a model change.

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "checker/collective.hpp"
#include "checker/interrupt.hpp"
#include "checker/property.hpp"
#include "cli/commands.hpp"
#include "cli/exit_status.hpp"
#include "cli/model_run.hpp"
#include "cli/output.hpp"
#include "cli/report_junit.hpp"
#include "cli/report_text.hpp"
#include "cli/time_note.hpp"

namespace cli {

namespace {

// The result of an entry that does not run distributed yet (collective.hpp): nothing
// covered, so incomplete, saying why.
checker::PropertyResult not_run_distributed(const checker::Property& property,
                                            const std::string& why) {
  checker::PropertyResult r;
  r.name = property.name;
  r.description = property.description;
  r.kind = checker::to_string(property.kind);
  r.verdict = checker::Verdict::incomplete;
  r.message = "not run: " + why;
  r.ranks = checker::distributed() ? static_cast<unsigned>(checker::distributed()->size()) : 1;
  r.coverage = {checker::Starts::sampled, 0, std::nullopt, "the start states",
                "none: not run under mpirun"};
  return r;
}

struct SuiteRow {
  const catalogue::ModelDefinition* definition = nullptr;
  const catalogue::SuiteEntry* entry = nullptr;
  catalogue::ParamValues values;
  ModelRun run;             // one result: this entry's property
  std::string shown_params; // the table's column: what the entry sets (see shown_params)

  const checker::PropertyResult& result() const { return run.results.front(); }
  bool as_expected() const { return result().verdict == entry->expected; }
};

struct Columns {
  std::size_t model = 5, params = 6, property = 8;
};

// The table names only the parameters the entry sets; the others are at their defaults
// (`tioa-check list`), so a row still reads as a command line that repeats it. The JSON
// and JUnit reports name every parameter.
std::string shown_params(const OrderedParams& all, const catalogue::ParamValues& set) {
  OrderedParams shown;
  for (const auto& param : all)
    if (set.count(param.first) != 0)
      shown.push_back(param);
  return shown.empty() ? "(defaults)" : format_params(shown);
}

void print_header(const Columns& c) {
  std::cout << fmt::format(
      "{:<{}}  {:<{}}  {:<{}}  {:<10}  {:<10}  {:>10}  {:>12}  {:>14}  {:>8}\n", "model", c.model,
      "params", c.params, "property", c.property, "verdict", "expected", "states", "edges",
      "worst time", "seconds");
}

void print_row(const Columns& c, const SuiteRow& row) {
  const checker::PropertyResult& r = row.result();
  std::cout << fmt::format(
      "{:<{}}  {:<{}}  {:<{}}  {:<10}  {:<10}  {:>10}  {:>12}  {:>14}  {:>8.3f}{}\n", row.run.model,
      c.model, row.shown_params, c.params, r.name, c.property, checker::to_string(r.verdict),
      checker::to_string(row.entry->expected), r.states, r.edges, format_worst_time(r), r.seconds,
      row.as_expected() ? "" : "   <- NOT AS EXPECTED");
}

std::vector<JunitSuite> junit_suites(const std::vector<SuiteRow>& rows) {
  std::vector<JunitSuite> suites;
  for (const auto& row : rows) {
    if (suites.empty() || suites.back().name != row.run.model)
      suites.push_back({row.run.model, {}, {}});
    const checker::PropertyResult& r = row.result();
    JunitCase c;
    c.name = r.name + " [" + format_params(row.run.params) + "]";
    c.seconds = r.seconds;
    if (!row.as_expected()) {
      c.outcome = JunitCase::Outcome::failed;
      c.message = std::string("expected ") + checker::to_string(row.entry->expected) + ", got " +
                  checker::to_string(r.verdict) + ": " + r.message;
      std::ostringstream details;
      print_property_block(details, row.run, r, TraceMode::text);
      c.details = details.str();
    }
    suites.back().cases.push_back(std::move(c));
  }
  return suites;
}

Json suite_json(const std::vector<SuiteRow>& rows, bool all_as_expected) {
  Json entries = Json::array();
  for (const auto& row : rows)
    entries.push_back(Json{
        {"model", row.run.model},
        {"params", params_json(row.run.params)},
        {"variant", row.run.variant.empty() ? Json(nullptr) : Json(row.run.variant)},
        {"time_note", row.run.quantum.empty() ? Json(nullptr) : Json(time_note(row.run.quantum))},
        {"property", row.entry->property},
        {"expected", checker::to_string(row.entry->expected)},
        {"result", property_json(row.run, row.result(), true)}});
  return Json{{"version", tool_version()},
              {"suite", std::move(entries)},
              {"all_as_expected", all_as_expected}};
}

} // namespace

int command_suite(const catalogue::Catalogue& models, const RunSettings& settings,
                  const std::vector<std::string>& only) {
  const auto started = std::chrono::steady_clock::now();
  for (const std::string& name : only)
    models.find(name); // an unknown model is a usage error, before anything runs
  // Resolve every entry first: a bad entry is reported before anything runs.
  std::vector<SuiteRow> rows;
  Columns columns;
  for (const auto& def : models)
    for (const auto& entry : def.suite) {
      if (!only.empty() && std::find(only.begin(), only.end(), def.name) == only.end())
        continue;
      SuiteRow row;
      row.definition = &def;
      row.entry = &entry;
      row.values = catalogue::resolve_params(def, param_settings(entry.params));
      row.run.model = def.name;
      row.run.params = ordered_params(def, row.values);
      row.run.variant = catalogue::variant_name(def, row.values);
      columns.model = std::max(columns.model, def.name.size());
      row.shown_params = shown_params(row.run.params, entry.params);
      columns.params = std::max(columns.params, row.shown_params.size());
      columns.property = std::max(columns.property, entry.property.size());
      rows.push_back(std::move(row));
    }
  auto junit = open_report_file(settings.junit_path);

  if (!settings.json)
    print_header(columns);
  checker::ExploreOptions options = explore_options(settings);
  // --max-seconds bounds the whole suite: each entry stops at the suite's deadline, and
  // the entries after it are not run.
  if (options.limits.max_seconds > 0)
    options.limits.deadline =
        started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double>(options.limits.max_seconds));
  std::map<std::pair<std::string, catalogue::ParamValues>, catalogue::ModelInstance> instances;
  for (auto& row : rows) {
    auto key = std::make_pair(row.definition->name, row.values);
    auto it = instances.find(key);
    if (it == instances.end())
      it = instances.emplace(key, row.definition->build(row.values)).first;
    const catalogue::ModelInstance& instance = it->second;
    const auto properties =
        select_properties(instance, row.definition->name, {row.entry->property});
    row.run.quantum = instance.quantum;
    row.run.layout = instance.system.layout();
    try {
      row.run.results.push_back(
          checker::run_property(instance.system, *properties.front(), options));
    } catch (const checker::NotDistributed& e) {
      // Under mpirun, an entry that does not run distributed yet is reported, not run,
      // and the entries after it still run.
      row.run.results.push_back(not_run_distributed(*properties.front(), e.what()));
    }
    if (!settings.json)
      print_row(columns, row);
    if (checker::interrupted() ||
        (options.limits.deadline && std::chrono::steady_clock::now() > *options.limits.deadline))
      break;
  }
  // A stop requested (SIGINT, SIGTERM) or the suite's time up: the entries not run are
  // left out of every report, and said to be.
  const std::size_t not_run = static_cast<std::size_t>(std::count_if(
      rows.begin(), rows.end(), [](const SuiteRow& r) { return r.run.results.empty(); }));
  rows.erase(std::remove_if(rows.begin(), rows.end(),
                            [](const SuiteRow& r) { return r.run.results.empty(); }),
             rows.end());
  const bool interrupted = checker::interrupted();
  const std::string stopped = interrupted   ? "interrupted (SIGINT or SIGTERM)"
                              : not_run > 0 ? "stopped at its time limit (--max-seconds)"
                                            : "";

  std::size_t as_expected = 0;
  bool contradicted = false; // a definite verdict other than the expected one
  VerdictCounts counts;
  for (const auto& row : rows) {
    as_expected += row.as_expected();
    contradicted = contradicted ||
                   (!row.as_expected() && row.result().verdict != checker::Verdict::incomplete);
    counts.add(row.result().verdict);
  }
  const bool all_as_expected = as_expected == rows.size();
  // Entries cut short by a limit (--max-states, --max-seconds) are not failures: exit 3,
  // as for check, unless some entry contradicts its expected verdict.
  const char* outcome = contradicted       ? "FAILED"
                        : interrupted      ? "INTERRUPTED"
                        : !stopped.empty() ? "INCOMPLETE"
                        : all_as_expected  ? "OK"
                                           : "INCOMPLETE";
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (settings.json) {
    Json json = suite_json(rows, all_as_expected);
    if (!stopped.empty()) {
      json["interrupted"] = interrupted;
      json["stopped"] = stopped;
      json["not_run"] = not_run;
    }
    print_json(json);
  } else {
    if (!stopped.empty())
      std::cout << "\nthe suite was " << stopped << "; " << not_run << " entries not run";
    std::cout << fmt::format("\nsuite: {} checks ({} hold, {} violated, {} incomplete), {} as "
                             "expected, {} not as expected, {:.2f} s: {}\n",
                             rows.size(), counts.holds, counts.violated, counts.incomplete,
                             as_expected, rows.size() - as_expected, seconds, outcome);
  }
  if (junit) {
    std::vector<JunitSuite> suites = junit_suites(rows);
    if (!stopped.empty()) { // one skipped case says so, where a CI page shows it
      JunitCase c;
      c.name = std::to_string(not_run) + " entries not run";
      c.outcome = JunitCase::Outcome::skipped;
      c.message = "the suite was " + stopped;
      suites.push_back({interrupted ? "interrupted" : "stopped", {}, {std::move(c)}});
    }
    write_junit(*junit, suites);
    junit->close();
    if (!*junit)
      throw catalogue::UsageError("cannot write the report file '" + settings.junit_path + "'");
  }
  if (contradicted)
    return some_violated;
  return !stopped.empty() || !all_as_expected ? some_incomplete : all_hold;
}

} // namespace cli
