#include "cli/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <fmt/format.h>

#include "checker/interrupt.hpp"
#include "cli/exit_status.hpp"
#include "cli/model_run.hpp"
#include "cli/output.hpp"
#include "cli/report_text.hpp"
#include "cli/run_system.hpp"

namespace cli {

namespace {

struct Range {
  std::string param;
  std::int64_t from = 0, to = 0;
};

constexpr std::int64_t max_values = 100000;

std::optional<std::int64_t> whole(const std::string& text) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty())
    return std::nullopt;
  return value;
}

// "seed=1..20": a whole-number parameter of the model and its range.
Range parse_range(const catalogue::ModelDefinition& model, const std::string& text) {
  const auto eq = text.find('=');
  const auto dots = text.find("..", eq == std::string::npos ? 0 : eq);
  const auto bad = [&](const std::string& why) {
    return catalogue::UsageError("--over '" + text + "': " + why);
  };
  if (eq == std::string::npos || dots == std::string::npos)
    throw bad("not of the form NAME=FROM..TO");
  Range r;
  r.param = text.substr(0, eq);
  const auto from = whole(text.substr(eq + 1, dots - eq - 1));
  const auto to = whole(text.substr(dots + 2));
  if (!from || !to)
    throw bad("FROM and TO must be whole numbers");
  r.from = *from;
  r.to = *to;
  const auto spec = std::find_if(model.params.begin(), model.params.end(),
                                 [&](const catalogue::ParamSpec& p) { return p.name == r.param; });
  if (spec == model.params.end() || spec->kind != catalogue::ParamKind::integer)
    throw bad("model '" + model.name + "' has no whole-number parameter '" + r.param + "'");
  if (r.from > r.to)
    throw bad("FROM is above TO");
  if (r.to - r.from >= max_values)
    throw bad("more than " + std::to_string(max_values) + " values");
  return r;
}

const char* verdict_word(checker::Verdict v) {
  switch (v) {
  case checker::Verdict::holds:
    return "holds";
  case checker::Verdict::violated:
    return "VIOLATED";
  case checker::Verdict::incomplete:
    return "incomplete";
  }
  return "?";
}

std::string cell(const checker::PropertyResult& r) {
  std::string text = verdict_word(r.verdict);
  if (r.verdict == checker::Verdict::violated && r.trace)
    text += " (" + std::to_string(r.trace->length()) + ")";
  return text;
}

struct Saved {
  std::string path, command;
};

// Writes the instance where something is violated; the command line that reproduces it
// names the file and every parameter the file does not stand for, when not at its default.
Saved save_instance(const catalogue::ModelDefinition& model, const BuiltModel& built,
                    const std::string& dir, const Range& range, std::int64_t value,
                    const std::vector<std::string>& violated) {
  Saved saved;
  saved.path = (std::filesystem::path(dir) /
                (model.name + "-" + range.param + "-" + std::to_string(value) + ".txt"))
                   .string();
  std::ofstream out(saved.path);
  out << model.instance_file(built.values);
  if (!out.flush())
    throw catalogue::UsageError("--save: cannot write " + saved.path);
  const auto& replaced = model.instance_file_replaces;
  saved.command =
      "tioa-check check " + model.name + " -p " + model.instance_file_param + "=" + saved.path;
  for (const auto& spec : model.params) {
    if (spec.name == range.param ||
        std::find(replaced.begin(), replaced.end(), spec.name) != replaced.end())
      continue;
    const auto& v = built.values.at(spec.name);
    if (v != spec.default_value)
      saved.command += " -p " + spec.name + "=" + v.text();
  }
  for (const auto& name : violated)
    saved.command += " --prop " + name;
  return saved;
}

} // namespace

int command_sweep(const catalogue::Catalogue& models, const ModelRequest& request,
                  const SweepSettings& sweep, const RunSettings& settings) {
  const catalogue::ModelDefinition& model = models.find(request.model);
  const Range range = parse_range(model, sweep.over);
  for (const auto& setting : request.param_settings)
    if (setting.rfind(range.param + "=", 0) == 0)
      throw catalogue::UsageError("parameter " + range.param + " is swept (--over " + sweep.over +
                                  "): do not set it with -p");
  if (!sweep.save_dir.empty()) {
    if (!model.instance_file)
      throw catalogue::UsageError("--save: model '" + model.name +
                                  "' cannot write its instances to files");
    std::error_code error;
    std::filesystem::create_directories(sweep.save_dir, error);
    if (error)
      throw catalogue::UsageError("--save: cannot create " + sweep.save_dir + ": " +
                                  error.message());
  }

  const checker::ExploreOptions options = explore_options(settings);
  std::map<std::string, VerdictCounts> counts;
  std::vector<std::string> names;
  std::vector<checker::PropertyResult> all;
  Json rows = Json::array();
  Json head;
  bool interrupted = false;
  std::size_t instances = 0;
  for (std::int64_t value = range.from; value <= range.to && !interrupted; ++value) {
    ModelRequest one = request;
    one.param_settings.push_back(range.param + "=" + std::to_string(value));
    const BuiltModel built = build_model(models, one);
    ++instances;
    const tioa::Automaton system = run_system(built, "start", "");
    ModelRun run = start_run(built, system);
    const auto properties = select_properties(built.instance, request.model, request.properties);
    if (value == range.from) {
      for (const auto* p : properties)
        names.push_back(p->name);
      OrderedParams shown;
      for (const auto& param : run.params)
        if (param.first != range.param)
          shown.push_back(param);
      head = run_header_json(run);
      head["params"] = params_json(shown);
      if (!settings.json) {
        std::cout << "sweep " << model.name << "  " << format_params(shown) << "\nover "
                  << range.param << "=" << range.from << ".." << range.to
                  << "  (VIOLATED (n): a counterexample of n steps)\n\n";
        std::cout << fmt::format("{:>10}", range.param);
        for (const auto& name : names)
          std::cout << fmt::format("  {:<{}}", name, std::max<std::size_t>(name.size(), 14));
        std::cout << fmt::format("  {:>10}\n", "states");
      }
    }
    std::vector<std::string> violated;
    std::uint64_t states = 0;
    for (const auto* p : properties) {
      run.results.push_back(checker::run_property(system, *p, options));
      const auto& r = run.results.back();
      counts[p->name].add(r.verdict);
      all.push_back(r);
      states = std::max(states, r.states);
      if (r.verdict == checker::Verdict::violated)
        violated.push_back(p->name);
      if (checker::stop_requested().load(std::memory_order_relaxed)) {
        interrupted = true;
        break;
      }
    }
    std::optional<Saved> saved;
    if (!violated.empty() && !sweep.save_dir.empty())
      saved = save_instance(model, built, sweep.save_dir, range, value, violated);
    if (settings.json) {
      Json row;
      row["value"] = value;
      row["properties"] = Json::array();
      for (const auto& r : run.results)
        row["properties"].push_back(property_json(run, r, false));
      row["saved"] = saved ? Json(saved->path) : Json(nullptr);
      row["reproduce"] = saved ? Json(saved->command) : Json(nullptr);
      rows.push_back(row);
      continue;
    }
    std::cout << fmt::format("{:>10}", value);
    for (std::size_t k = 0; k < names.size(); ++k)
      std::cout << fmt::format("  {:<{}}",
                               k < run.results.size() ? cell(run.results[k]) : "not run",
                               std::max<std::size_t>(names[k].size(), 14));
    std::cout << fmt::format("  {:>10}\n", states);
    if (saved)
      std::cout << fmt::format("{:>10}  saved: {}\n{:>10}  reproduce: {}\n", "", saved->path, "",
                               saved->command);
    std::cout.flush();
  }

  if (settings.json) {
    Json out = head;
    out["over"] = {{"param", range.param}, {"from", range.from}, {"to", range.to}};
    out["instances"] = instances;
    out["rows"] = rows;
    Json summary = Json::object();
    for (const auto& name : names)
      summary[name] = {{"holds", counts[name].holds},
                       {"violated", counts[name].violated},
                       {"incomplete", counts[name].incomplete}};
    out["summary"] = summary;
    out["interrupted"] = interrupted;
    print_json(out);
  } else {
    std::cout << "\nsummary over " << instances << " instances"
              << (interrupted ? " (interrupted)" : "") << ":\n";
    for (const auto& name : names)
      std::cout << fmt::format("  {:<26} holds {:>5}  violated {:>5}  incomplete {:>5}\n", name,
                               counts[name].holds, counts[name].violated, counts[name].incomplete);
  }
  return interrupted && exit_status(all) == all_hold ? some_incomplete : exit_status(all);
}

} // namespace cli
