#pragma once
// `replay MODEL FILE`: re-executes every trace of a --trace-out file (trace_file.hpp) on
// the model the file names, with the file's parameters: each step must be enabled in the
// state before it, carry its action (name, parameters, choice) and reach the state the file
// gives, at the time it gives; a lasso must close; the first state must be a start state of
// the run that wrote it. Then the property is evaluated again on the trace: the last state
// breaks the invariant, has no step (a deadlock, a time-lock), leaves the legal set (a
// closure step), or the loop stays outside it (a lasso).

#include <string>

#include "catalogue/registry.hpp"

namespace cli {

// Exit code: 0 when every trace replays and shows what it claims, 1 when one does not,
// 2 for a file that is not a trace file of this model.
int command_replay(const catalogue::Catalogue& models, const std::string& model,
                   const std::string& path, bool json);

} // namespace cli
