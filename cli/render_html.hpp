#pragma once
// One self-contained HTML page of a run's traces (--html FILE): a title with the model, its
// parameters, each property and its verdict; then, for each property with a trace, its
// frames in order, each headed by the action that led to it and its time, with step
// controls (a few lines of inline script; without script every frame shows, stacked).
// The picture of a frame is the model's own where it has one (ModelDefinition::picture,
// with the table of every variable folded underneath) and otherwise a table of the
// variables, the changed ones highlighted. No external resource: inline CSS,
// inline SVG, inline script. The page is also well-formed XML.

#include <ostream>

#include "catalogue/registry.hpp"
#include "cli/report_json.hpp"

namespace cli {

// `report` is run_json(run, true) (report_json.hpp); `picture` the model's (may be empty).
// `explain`, when the model has one, adds its line on each state to the frame; frames of a
// trace with a legal set say whether the state is in it.
void write_html(std::ostream& out, const Json& report, const catalogue::Picture& picture = {},
                const catalogue::Explain& explain = {});

} // namespace cli
