#include "cli/report_json.hpp"

#include <algorithm>
#include <charconv>

#include "checker/trace.hpp"
#include "cli/report_text.hpp"
#include "cli/time_note.hpp"

namespace cli {

namespace {

// A variable's value as JSON: numbers for integers and clocks, true/false for booleans,
// strings for enumerations and ⊥, arrays of element names for sets.
Json value_json(const tioa::VariableInfo& variable, const std::string& text) {
  switch (variable.kind) {
  case tioa::VariableKind::boolean:
    if (text == "true" || text == "false")
      return text == "true";
    break;
  case tioa::VariableKind::integer:
  case tioa::VariableKind::clock: {
    std::int64_t number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (error == std::errc() && end == text.data() + text.size())
      return number;
    break;
  }
  case tioa::VariableKind::set: {
    Json elements = Json::array();
    for (std::size_t start = 1; start + 1 < text.size();) {
      const std::size_t end = std::min(text.find(", ", start), text.size() - 1);
      elements.push_back(text.substr(start, end - start));
      start = end + 2;
    }
    return elements;
  }
  default:
    break;
  }
  return text;
}

// A figure's value: a number when the whole text is one, else the text ("1/2", "n/a").
Json figure_json(const std::string& text) {
  std::int64_t whole = 0;
  const char* end = text.data() + text.size();
  if (auto [at, error] = std::from_chars(text.data(), end, whole);
      error == std::errc() && at == end)
    return whole;
  double number = 0;
  if (auto [at, error] = std::from_chars(text.data(), end, number);
      error == std::errc() && at == end && !text.empty())
    return number;
  return text;
}

} // namespace

Json action_json(const checker::TraceStep& step) {
  if (step.action.empty())
    return nullptr;
  Json out;
  out["name"] = step.call.name.empty() ? step.action : step.call.name;
  Json params = Json::object();
  for (const auto& [name, value] : step.call.params)
    params[name] = value;
  out["params"] = std::move(params);
  if (step.call.choice != 0)
    out["choice"] = step.call.choice;
  out["text"] = step.action;
  return out;
}

Json trace_json(const tioa::StateLayout& system_layout, const checker::PropertyResult& result) {
  const checker::Trace& trace = *result.trace;
  const tioa::StateLayout& layout = result.trace_layout_or(system_layout);
  Json steps = Json::array();
  const auto& variables = layout.variables();
  const bool marked = result.trace_in_legal_set.size() == trace.steps.size();
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const checker::TraceStep& step = trace.steps[i];
    Json state = Json::object();
    const auto rendered = checker::render_state(layout, step.state.data());
    for (std::size_t v = 0; v < rendered.size(); ++v)
      state[rendered[v].first] = value_json(variables[v], rendered[v].second);
    Json item;
    item["action"] = action_json(step);
    item["time"] = step.time;
    item["state"] = std::move(state);
    if (marked)
      item["in_legal_set"] = static_cast<bool>(result.trace_in_legal_set[i]);
    steps.push_back(std::move(item));
  }
  Json out;
  out["role"] = result.trace_role;
  out["kind"] = result.trace_kind;
  out["loop_start"] = trace.loop_start ? Json(*trace.loop_start) : Json(nullptr);
  out["length"] = trace.length();
  if (marked)
    out["legal_set"] = result.legal_set_name;
  // A trace of another automaton than the system (ModelInstance::trace_systems): replay
  // replays it there.
  if (!result.trace_system_name.empty())
    out["system"] = result.trace_system_name;
  out["steps"] = std::move(steps);
  return out;
}

Json property_json(const ModelRun& run, const checker::PropertyResult& r, bool with_trace) {
  Json out;
  out["name"] = r.name;
  out["kind"] = r.kind;
  out["description"] = r.description;
  out["verdict"] = checker::to_string(r.verdict);
  out["message"] = r.message;
  out["states"] = r.states;
  out["edges"] = r.edges;
  out["depth"] = r.depth;
  out["seconds"] = r.seconds;
  out["threads"] = r.threads;
  out["ranks"] = r.ranks;
  out["por"] = r.por;
  if (r.por)
    out["reduced_states"] = r.reduced_states;
  out["store"] = r.store;
  if (r.omission_probability)
    out["omission_probability"] = *r.omission_probability;
  Json coverage;
  coverage["starts"] = checker::to_string(r.coverage.starts);
  coverage["count"] = r.coverage.count;
  coverage["of"] = r.coverage.of ? Json(*r.coverage.of) : Json(nullptr);
  coverage["over"] = r.coverage.over;
  coverage["chosen"] = r.coverage.chosen;
  coverage["instance"] = run.model + (run.params.empty() ? "" : " " + format_params(run.params));
  out["coverage"] = std::move(coverage);
  out["time_unit"] = r.time_unit;
  const bool timing_kind = r.kind == "stabilisation" || r.kind == "transitivity";
  if (timing_kind && r.worst_time)
    out["worst_time"] = *r.worst_time;
  if (timing_kind && r.last_time_outside)
    out["last_time_outside"] = *r.last_time_outside;
  out["notes"] = r.notes;
  Json figures = Json::object();
  for (const auto& [name, value] : r.figures)
    figures[name] = figure_json(value);
  out["figures"] = std::move(figures);
  if (with_trace && r.trace)
    out["trace"] = trace_json(run.layout, r);
  if (!r.witnesses.empty()) {
    Json witnesses = Json::array();
    for (const std::string& text : r.witnesses)
      witnesses.push_back(Json::parse(text));
    out["witnesses"] = std::move(witnesses);
  }
  return out;
}

Json param_json(const catalogue::ParamValue& value) {
  if (!value.is_number()) // a choice or a text
    return value.text();
  if (value.whole())
    return value.integer();
  return value.text();
}

Json params_json(const OrderedParams& params) {
  Json out = Json::object();
  for (const auto& [name, value] : params)
    out[name] = param_json(value);
  return out;
}

const char* tool_version() {
  return TIOA_CHECK_VERSION;
}

Json run_header_json(const ModelRun& run) {
  Json out;
  out["version"] = tool_version();
  out["model"] = run.model;
  out["params"] = params_json(run.params);
  out["variant"] = run.variant.empty() ? Json(nullptr) : Json(run.variant);
  if (!run.from.empty())
    out["from"] = run.from;
  if (!run.start.empty())
    out["start"] = run.start; // the start states were every state where it holds
  if (!run.invariant.empty())
    out["invariant"] = run.invariant;
  return out;
}

Json run_json(const ModelRun& run, bool with_trace) {
  Json out = run_header_json(run);
  if (!run.quantum.empty()) {
    out["quantum"] = run.quantum;
    out["time_note"] = time_note(run.quantum); // once per report: it is the same for each
  }
  Json properties = Json::array();
  for (const auto& r : run.results)
    properties.push_back(property_json(run, r, with_trace));
  out["properties"] = std::move(properties);
  if (run.interrupted) {
    out["interrupted"] = true;
    out["not_run"] = run.not_run;
  }
  return out;
}

} // namespace cli
