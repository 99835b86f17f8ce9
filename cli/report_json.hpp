#pragma once
// The machine-readable report (--json): one JSON object on stdout.

#include <nlohmann/json.hpp>

#include "checker/result.hpp"
#include "cli/model_run.hpp"

namespace cli {

using Json = nlohmann::ordered_json; // keys in the order written

// A step's action: {"name", "params": {name: value}, ["choice"], "text"}; null for the first
// state.
Json action_json(const checker::TraceStep& step);

// {"role", "kind", "loop_start" (or null), "length", "steps": [{"action" (null for the
// first state), "time", "state": {variable: value}}]}
Json trace_json(const tioa::StateLayout& layout, const checker::PropertyResult& result);

// One property: name, kind, description, verdict, message, figures of the run, and the
// trace when there is one and `with_trace`.
Json property_json(const ModelRun& run, const checker::PropertyResult& result, bool with_trace);

// A whole number as a JSON number, a fraction as a string ("9/10").
Json param_json(const catalogue::ParamValue& value);
Json params_json(const OrderedParams& params);

// {"model", "params", ("from",) "properties": [...]}
// The version of tioa-check that wrote a report (the JSON field `version`).
const char* tool_version();

// {"version", "model", "params", "variant", ["from"], ["start"], ["invariant"]}: how a run
// began, the head of the report and of the trace file.
Json run_header_json(const ModelRun& run);

Json run_json(const ModelRun& run, bool with_trace);

} // namespace cli
