#pragma once
// Where reports go: JSON on stdout, a JUnit file opened before any check runs (so that a
// path that cannot be written is a usage error, not a lost report).

#include <fstream>
#include <optional>
#include <string>

#include "cli/report_json.hpp"

namespace cli {

void print_json(const Json& json);

// Opens `path` for writing (nothing when empty); throws UsageError when it cannot.
std::optional<std::ofstream> open_report_file(const std::string& path);

} // namespace cli
