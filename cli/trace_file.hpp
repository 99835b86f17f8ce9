#pragma once
// Traces out and in: --trace-out writes every counterexample and witness of a run as one
// JSON document, and `replay` reads such a document back into states of a model.
//
// {"version", "model", "params", "variant", ["from"], ["start"], ["invariant"],
//  "traces": [{"property", "verdict", "role", "kind", "loop_start", "length",
//              ["last_time_outside"], ["legal_set"],
//              "steps": [{"action", "time", "state", ["in_legal_set"]}]}],
//  "witnesses": [{"property", "role", "kind", "claim", ...}]}
// A step is as in the --json report (report_json.hpp): the action {"name", "params",
// ["choice"], "text"} (null for the first state) and the state as variable -> value.

#include <fstream>
#include <string>
#include <vector>

#include "cli/model_run.hpp"
#include "cli/report_json.hpp"

namespace cli {

Json trace_document(const ModelRun& run);

// Writes the document to `file` (opened by open_report_file before the run); throws
// UsageError when the write fails.
void write_trace_file(std::ofstream& file, const std::string& path, const ModelRun& run);

// The state a step's "state" object describes: every variable of the layout exactly once,
// each with a value of its domain, written as the reports write them. Throws UsageError,
// prefixed by `where` ("step 3"), naming what is wrong.
std::vector<tioa::Word> state_from_json(const tioa::StateLayout& layout, const Json& state,
                                        const std::string& where);

} // namespace cli
