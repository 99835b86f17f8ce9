#pragma once
// The human-readable report: one block per property, with its trace as a numbered list.

#include <iosfwd>
#include <string>

#include "checker/result.hpp"
#include "cli/model_run.hpp"
#include "cli/settings.hpp"

namespace cli {

// "N=5 K=4"
std::string format_params(const OrderedParams& params);

// "paper (the algorithm as the paper gives it)", or the variant settings and that they
// change the paper's algorithm.
std::string variant_text(const std::string& variant);

// The value as text; an empty text as "", so that it is seen.
std::string format_value(const catalogue::ParamValue& value);

// "24 steps", or "-" when the run measured no worst time.
std::string format_worst_time(const checker::PropertyResult& result);

// The whole report of a check or explore run: a header, then one block per property,
// then a summary line.
void print_text_report(std::ostream& out, const ModelRun& run, TraceMode trace);

// One property's block (also the body of a JUnit failure).
void print_property_block(std::ostream& out, const ModelRun& run,
                          const checker::PropertyResult& result, TraceMode trace);

// The trace as a numbered list: step, action, time, and the variables that changed (the
// whole first state); a lasso marks where its loop starts.
void print_trace(std::ostream& out, const tioa::StateLayout& layout, const checker::Trace& trace,
                 const std::string& indent);

} // namespace cli
