#pragma once
// The picture of a state that works for every model: a table of its variables by name, the
// values that changed since the previous step highlighted.

#include <ostream>

#include "cli/report_json.hpp"

namespace cli {

// `state` and `previous` are a trace step's "state" objects (report_json.hpp); `previous`
// is null for the first step (nothing is highlighted then).
void write_state_table(std::ostream& out, const Json& state, const Json* previous);

} // namespace cli
