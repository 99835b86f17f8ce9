#include "cli/report_text.hpp"

#include <algorithm>
#include <cctype>
#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "checker/trace.hpp"
#include "cli/exit_status.hpp"
#include "cli/report_json.hpp"
#include "cli/time_note.hpp"
#include "support/text.hpp"

namespace cli {

namespace {

// Words of `text` on lines of at most `width` characters, each line after `indent`.
void print_wrapped(std::ostream& out, const std::string& text, const std::string& indent,
                   std::size_t width) {
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out << indent << line << '\n';
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty())
    out << indent << line << '\n';
}

void print_indented(std::ostream& out, const std::string& text, const std::string& indent) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
    out << indent << line << '\n';
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

} // namespace

std::string format_params(const OrderedParams& params) {
  std::string text;
  for (const auto& [name, value] : params)
    text += (text.empty() ? "" : " ") + name + "=" + format_value(value);
  return text;
}

std::string variant_text(const std::string& variant) {
  return variant == "paper" ? "paper (the algorithm as the paper gives it)"
                            : variant + " (changed from the paper's algorithm)";
}

std::string format_value(const catalogue::ParamValue& value) {
  return value.is_text() && value.text().empty() ? "\"\"" : value.text();
}

std::string format_worst_time(const checker::PropertyResult& result) {
  if (!result.worst_time)
    return "-";
  return std::to_string(*result.worst_time) + " " + result.time_unit;
}

void print_trace(std::ostream& out, const tioa::StateLayout& layout, const checker::Trace& trace,
                 const std::string& indent) {
  std::size_t action_width = 7; // "(start)"
  std::uint64_t last_time = 0;
  for (const auto& step : trace.steps) {
    action_width = std::max(action_width, step.action.size());
    last_time = std::max(last_time, step.time);
  }
  const std::size_t number_width = std::to_string(trace.steps.size()).size();
  const std::size_t time_width = std::to_string(last_time).size();

  std::vector<std::pair<std::string, std::string>> previous;
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const auto& step = trace.steps[i];
    const auto state = checker::render_state(layout, step.state.data());
    std::string changes;
    for (std::size_t v = 0; v < state.size(); ++v)
      if (i == 0 || state[v].second != previous[v].second)
        changes += (changes.empty() ? "" : " ") + state[v].first + "=" + state[v].second;
    if (changes.empty())
      changes = "(no change)";
    const std::string action = i == 0 ? "(start)" : step.action;
    const bool loop_here = trace.loop_start && *trace.loop_start == i;
    out << indent
        << fmt::format("{:>{}}  {:<{}}  t={:<{}}  {}{}\n", i, number_width, action, action_width,
                       step.time, time_width, changes, loop_here ? "   <- loop starts here" : "");
    previous = state;
  }
  if (trace.loop_start)
    out << indent << "(the last state is the state of step " << *trace.loop_start
        << ": the loop repeats forever)\n";
}

void print_property_block(std::ostream& out, const ModelRun& run, const checker::PropertyResult& r,
                          TraceMode trace) {
  out << "== " << r.name << " (" << r.kind << "): " << upper(checker::to_string(r.verdict)) << '\n';
  if (!r.description.empty())
    out << "   " << r.description << '\n';
  out << "   " << r.message << '\n';
  out << fmt::format("   states {}  edges {}  depth {}  seconds {:.3f}  threads {}{}\n", r.states,
                     r.edges, r.depth, r.seconds, r.threads,
                     r.ranks > 1 ? fmt::format("  ranks {}", r.ranks) : "");
  out << "   coverage: " << checker::describe(r.coverage) << '\n';
  if (r.por && r.reduced_states > 0) // with none, the graph explored is the full one
    out << "   zero-time steps reduced (--por on): " << r.reduced_states
        << " states expanded in part; the counts are the reduced graph's\n";
  if (r.omission_probability)
    out << "   store: " << r.store << " (64-bit), omission probability ≤ "
        << checker::format_probability(*r.omission_probability) << '\n';
  if (r.worst_time) {
    out << "   worst time: " << format_worst_time(r);
    if (r.last_time_outside)
      out << " (last time outside: " << *r.last_time_outside << " " << r.time_unit << ")";
    out << '\n';
  }
  for (const auto& [name, value] : r.figures)
    out << "   " << name << ": " << value << '\n';
  for (const auto& note : r.notes)
    print_wrapped(out, "note: " + note, "   ", 90);
  if (r.trace && trace != TraceMode::none) {
    out << "   " << r.trace_role << " (" << r.trace_kind << "), " << r.trace->length()
        << (r.trace->length() == 1 ? " step" : " steps");
    if (r.trace->loop_start)
      out << ", loop from step " << *r.trace->loop_start;
    out << ":\n";
    if (trace == TraceMode::json)
      print_indented(out,
                     trace_json(run.layout, r).dump(2, ' ', false, Json::error_handler_t::replace),
                     "     ");
    else
      print_trace(out, r.trace_layout_or(run.layout), *r.trace, "     ");
  }
}

void print_text_report(std::ostream& out, const ModelRun& run, TraceMode trace) {
  out << run.model;
  if (!run.params.empty())
    out << "  " << format_params(run.params);
  if (!run.start.empty())
    out << "  (from every state where " << run.start << ")";
  else if (run.from == "arbitrary")
    out << "  (" << run.command
        << " from arbitrary states: U(A), every valuation is a start state)";
  else if (run.from == "start")
    out << "  (" << run.command << " from the model's start states)";
  if (!run.variant.empty())
    out << "\nvariant: " << variant_text(run.variant);
  out << "\n\n";
  VerdictCounts counts;
  for (const auto& r : run.results) {
    print_property_block(out, run, r, trace);
    out << '\n';
    counts.add(r.verdict);
  }
  if (!run.quantum.empty()) { // once per report: it is the same for every property
    print_wrapped(out, "time: " + time_note(run.quantum), "", 90);
    out << '\n';
  }
  if (run.interrupted)
    out << "interrupted: the run was stopped (SIGINT or SIGTERM)"
        << (run.not_run.empty() ? std::string("") : "; not run: " + support::join(run.not_run))
        << "\n";
  out << fmt::format("summary: {} {}: {} hold, {} violated, {} incomplete\n", run.results.size(),
                     run.results.size() == 1 ? "property" : "properties", counts.holds,
                     counts.violated, counts.incomplete);
}

} // namespace cli
