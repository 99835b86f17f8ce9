#include "cli/render_html.hpp"

#include <string>

#include "cli/html_text.hpp"
#include "cli/render_table.hpp"
#include "cli/report_text.hpp"

namespace cli {

namespace {

// Inline CSS: frames as cards; a changed value, a failed VSA or robot, a message stand out.
constexpr const char* style = R"(
body { font-family: sans-serif; margin: 1.5em; color: #222; max-width: 60em; }
h1 { font-size: 1.4em; } h2 { font-size: 1.2em; margin-top: 2em; }
.verdict-holds { color: #1a7f37; } .verdict-violated { color: #c62828; }
.verdict-incomplete { color: #b26a00; }
.frame { border: 1px solid #ccc; border-radius: 6px; padding: 0.6em 1em; margin: 0.8em 0; }
.frame h3 { font-size: 1em; margin: 0 0 0.5em 0; }
.loop { border-color: #7b1fa2; }
.frame.in-l { border-left: 6px solid #1a7f37; } .frame.out-l { border-left: 6px solid #c62828; }
.legal { margin: 0 0 0.5em 0; } .legal b.in { color: #1a7f37; } .legal b.out { color: #c62828; }
table.state { border-collapse: collapse; font-family: monospace; }
table.state td, table.state th { border: 1px solid #ddd; padding: 0.15em 0.6em; text-align: left; }
tr.changed td { background: #fff3b0; font-weight: bold; } .was { color: #777; font-weight: normal; }
.controls button { font-size: 1em; margin-right: 0.4em; } .status { font-weight: bold; }
svg.vlayer { background: #fff; }
rect.region { stroke: #555; stroke-width: 1.5; } rect.live { fill: #e8f5e9; }
rect.failed { fill: #eeeeee; stroke-dasharray: 6 4; }
circle.point { fill: #999; } line.curve { stroke: #1565c0; stroke-width: 3; opacity: 0.6; }
text { font-size: 11px; } text.curve-label { fill: #1565c0; font-size: 14px; }
circle.robot { fill: #ef6c00; stroke: #222; } circle.robot.failed { fill: #9e9e9e; }
text.robot-label { text-anchor: middle; fill: #fff; font-weight: bold; }
line.to-target { stroke: #ef6c00; stroke-dasharray: 4 3; } path.target { stroke: #ef6c00; stroke-width: 2; }
line.msg { stroke-width: 2; } line.cn-update { stroke: #6a1b9a; } line.vn-update { stroke: #00838f; }
line.target-update { stroke: #c62828; } li.message { color: #6a1b9a; }
svg.path-reservation { background: #fff; }
rect.plane-cell { fill: #fafafa; stroke: #bbb; } text.axis { fill: #888; text-anchor: middle; }
polyline.path { stroke-width: 1.5; opacity: 0.8; }
rect.requested { stroke-width: 1.5; stroke-dasharray: 4 3; }
text.zone-mark { font-size: 9px; } text.zone-mark.post { text-anchor: end; }
rect.collision { fill: none; stroke: #c62828; stroke-width: 2.5; }
circle.robot-disc { stroke: #222; } circle.halted-ring { fill: none; stroke: #c62828; stroke-width: 3; }
text.exception-label { fill: #c62828; text-anchor: middle; font-weight: bold; }
text.msg-label { font-size: 9px; text-anchor: middle; }
text.msg-label, text.exception-label, text.zone-mark { paint-order: stroke; stroke: #fff; stroke-width: 3px; } li.collision { color: #c62828; font-weight: bold; }
table.robots { border-collapse: collapse; margin-top: 0.4em; }
table.robots td, table.robots th { border: 1px solid #ddd; padding: 0.15em 0.6em; text-align: left; }
span.swatch { display: inline-block; width: 0.8em; height: 0.8em; border-radius: 50%; }
details { margin-top: 0.5em; }
)";

// Step controls: show one frame at a time (buttons, a slider, the arrow keys). Written
// without '<' and '&' so that the page stays well-formed XML.
constexpr const char* script = R"(
for (const trace of document.querySelectorAll('.trace')) {
  const frames = Array.from(trace.querySelectorAll('.frame'));
  const slider = trace.querySelector('.slider');
  const status = trace.querySelector('.status');
  let at = 0;
  const show = (i) => {
    at = Math.max(0, Math.min(frames.length - 1, i));
    frames.forEach((frame, j) => { frame.hidden = j !== at; });
    slider.value = at;
    status.textContent = 'step ' + at + ' of ' + (frames.length - 1);
  };
  trace.querySelector('.first').onclick = () => show(0);
  trace.querySelector('.prev').onclick = () => show(at - 1);
  trace.querySelector('.next').onclick = () => show(at + 1);
  trace.querySelector('.last').onclick = () => show(frames.length - 1);
  trace.querySelector('.all').onclick = () => { frames.forEach((frame) => { frame.hidden = false; }); status.textContent = 'all steps'; };
  slider.max = frames.length - 1;
  slider.oninput = () => show(Number(slider.value));
  trace.tabIndex = 0;
  trace.onkeydown = (event) => { if (event.key === 'ArrowRight') show(at + 1); if (event.key === 'ArrowLeft') show(at - 1); };
  trace.querySelector('.controls').hidden = false;
  show(0);
}
)";

// A string as it is, but an empty one as "" (as the text report writes an empty text
// parameter), so that "name=" never looks like a value was lost.
std::string scalar_text(const Json& value) {
  if (!value.is_string())
    return value.dump();
  return value.get<std::string>().empty() ? "\"\"" : value.get<std::string>();
}

std::string params_text(const Json& params) {
  std::string out;
  for (const auto& [name, value] : params.items())
    out += (out.empty() ? "" : ", ") + name + "=" + scalar_text(value);
  return out;
}

// The model's line on a state (catalogue::Explain), or "" when it has none or it cannot
// read this state.
std::string explanation(const catalogue::Explain& explain, const Json& report, const Json& state) {
  if (!explain)
    return "";
  try {
    return explain(report["params"], state);
  } catch (const std::exception&) {
    return "";
  }
}

void write_frame(std::ostream& out, const Json& report, const catalogue::Picture& picture,
                 const catalogue::Explain& explain, const Json& trace, const std::string& trace_id,
                 std::size_t index) {
  const Json& steps = trace["steps"];
  const Json& step = steps[index];
  const bool loop_start = trace["loop_start"].is_number() && trace["loop_start"] == index;
  const bool marked = step.contains("in_legal_set") && step["in_legal_set"].is_boolean();
  const bool in_legal_set = marked && step["in_legal_set"].get<bool>();
  out << "<section class=\"frame" << (loop_start ? " loop" : "")
      << (marked ? (in_legal_set ? " in-l" : " out-l") : "") << "\" data-step=\"" << index
      << "\">\n<h3>step " << index << ": ";
  if (step["action"].is_null())
    out << "start state";
  else
    out << "after <code>" << html_text(step["action"]["text"].get<std::string>()) << "</code>";
  out << ", t = " << step["time"].dump();
  if (loop_start)
    out << " <span class=\"loop-note\">(the loop starts here)</span>";
  if (trace["loop_start"].is_number() && index + 1 == steps.size())
    out << " <span class=\"loop-note\">(the same state as step " << trace["loop_start"].dump()
        << ": the loop repeats forever)</span>";
  out << "</h3>\n";
  // A stabilisation witness is read by where it is against L, and why (issue 17).
  const std::string why = explanation(explain, report, step["state"]);
  if (marked)
    out << "<p class=\"legal\"><b class=\"" << (in_legal_set ? "in" : "out") << "\">"
        << (in_legal_set ? "in L" : "outside L") << "</b> ("
        << html_text(scalar_text(trace.value("legal_set", Json("L")))) << ")"
        << (why.empty() ? "" : "; " + html_text(why)) << "</p>\n";
  else if (!why.empty())
    out << "<p class=\"legal\">" << html_text(why) << "</p>\n";
  const Json* previous = index == 0 ? nullptr : &steps[index - 1]["state"];
  const std::string picture_id = trace_id + "-" + std::to_string(index);
  if (picture) {
    picture(out, report["params"], step["state"], picture_id);
    out << "<details><summary>every variable</summary>\n";
    write_state_table(out, step["state"], previous);
    out << "</details>\n";
  } else {
    write_state_table(out, step["state"], previous);
  }
  out << "</section>\n";
}

void write_trace(std::ostream& out, const Json& report, const catalogue::Picture& picture,
                 const catalogue::Explain& explain, const Json& trace,
                 const std::string& trace_id) {
  const Json& steps = trace["steps"];
  out << "<p>" << html_text(scalar_text(trace["role"])) << " ("
      << html_text(scalar_text(trace["kind"])) << "), " << trace["length"].dump() << " steps, "
      << steps.size() << " frames.</p>\n";
  out << "<div class=\"trace\">\n<p class=\"controls\" hidden=\"hidden\">"
         "<button class=\"first\">first</button><button class=\"prev\">previous</button>"
         "<button class=\"next\">next</button><button class=\"last\">last</button>"
         "<button class=\"all\">show all</button> <input class=\"slider\" type=\"range\" "
         "min=\"0\" max=\"0\" value=\"0\"/> <span class=\"status\"></span></p>\n";
  for (std::size_t i = 0; i < steps.size(); ++i)
    write_frame(out, report, picture, explain, trace, trace_id, i);
  out << "</div>\n";
}

} // namespace

void write_html(std::ostream& out, const Json& report, const catalogue::Picture& picture,
                const catalogue::Explain& explain) {
  const std::string model = scalar_text(report["model"]);
  const std::string params = params_text(report["params"]);
  out << "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n"
         "<meta charset=\"utf-8\"/>\n<title>tioa-check: "
      << html_text(model) << " (" << html_text(params) << ")</title>\n<style>" << style
      << "</style>\n</head>\n<body>\n";
  out << "<h1>tioa-check: <code>" << html_text(model) << "</code></h1>\n";
  out << "<p>parameters: <code>" << html_text(params) << "</code>";
  if (report.contains("variant") && report["variant"].is_string())
    out << "; variant: " << html_text(variant_text(scalar_text(report["variant"])));
  if (report.contains("from"))
    out << "; start states: " << html_text(scalar_text(report["from"]));
  if (report.contains("quantum"))
    out << "; one time step: " << html_text(scalar_text(report["quantum"]));
  out << "</p>\n<ul class=\"verdicts\">\n";
  for (const Json& property : report["properties"]) {
    const std::string verdict = scalar_text(property["verdict"]);
    out << "<li><b>" << html_text(scalar_text(property["name"])) << "</b> ("
        << html_text(scalar_text(property["kind"])) << "): <span class=\"verdict-"
        << html_text(verdict) << "\">" << html_text(verdict)
        << "</span>: " << html_text(scalar_text(property["message"]));
    if (property.contains("coverage")) {
      const Json& coverage = property["coverage"];
      out << " <i>(covered: " << html_text(scalar_text(coverage["starts"])) << ", "
          << html_text(scalar_text(coverage["count"]));
      if (!coverage["of"].is_null())
        out << " of " << html_text(scalar_text(coverage["of"]));
      out << ": " << html_text(scalar_text(coverage["over"]));
      if (coverage.contains("chosen") && !coverage["chosen"].get<std::string>().empty())
        out << ", " << html_text(scalar_text(coverage["chosen"]));
      out << ")</i>";
    }
    out << "</li>\n";
  }
  out << "</ul>\n";
  bool any_trace = false;
  std::size_t number = 0;
  for (const Json& property : report["properties"]) {
    ++number;
    if (!property.contains("trace"))
      continue;
    any_trace = true;
    out << "<h2>" << html_text(scalar_text(property["name"])) << ": "
        << html_text(scalar_text(property["verdict"])) << "</h2>\n<p>"
        << html_text(scalar_text(property["description"])) << "</p>\n";
    write_trace(out, report, picture, explain, property["trace"], "p" + std::to_string(number));
  }
  if (!any_trace)
    out << "<p>No property has a trace to show.</p>\n";
  out << "<script>" << script << "</script>\n</body>\n</html>\n";
}

} // namespace cli
