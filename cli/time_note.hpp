#pragma once
// What a result over discretised (integer) time says about the dense-time model.

#include <string>

namespace cli {

// The note every verdict of a timed model carries; `quantum` says what one tick is.
std::string time_note(const std::string& quantum);

} // namespace cli
