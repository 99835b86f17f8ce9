#pragma once
// What the command line asked for, shared by the commands: how to run the checks and how
// to report them.

#include <string>
#include <vector>

#include "checker/options.hpp"

namespace cli {

// How a trace is shown: as a numbered list in the text report, as a JSON object (also in
// the text report), or not at all. A --json report carries the trace unless `none`.
enum class TraceMode { text, json, none };

struct RunSettings {
  unsigned threads = 1;
  bool por = true;                                      // --por on|off (or all)
  bool por_stabilisation = false;                       // --por all
  checker::StoreKind store = checker::StoreKind::exact; // --store (check, explore)
  checker::Limits limits;
  bool json = false;
  std::string junit_path; // empty: no JUnit file
  std::string html_path;  // empty: no HTML page of the traces (check, explore)
  TraceMode trace = TraceMode::text;
  std::string trace_out_path; // --trace-out: every trace as JSON to this file (trace_file.hpp)
  std::string dot_path;       // --dot: the state graph to this file (state_graph.hpp)
  // --counterexample-out (check): the first counterexample that carries an instance of its
  // own (mc-round: a round configuration) to this file (counterexample_file.hpp)
  std::string counterexample_out_path;
  std::string start;     // --start: a start predicate (checker/state_expression.hpp)
  std::string invariant; // --invariant: an invariant to check besides the model's
};

// What `check` and `explore` run: a model, its parameter settings ("name=value") and the
// properties asked for (empty: the command's default set).
struct ModelRequest {
  std::string model;
  std::vector<std::string> param_settings;
  std::vector<std::string> properties;
};

} // namespace cli
