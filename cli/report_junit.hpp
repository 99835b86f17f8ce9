#pragma once
// JUnit XML for CI: one <testsuite> per model, one <testcase> per property. A failed case
// carries <failure message=...> with the text report of the property as its body; a
// skipped one (a limit was hit) carries <skipped message=...>.

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "cli/model_run.hpp"
#include "cli/settings.hpp"

namespace cli {

struct JunitCase {
  enum class Outcome { passed, failed, skipped };
  std::string name;
  Outcome outcome = Outcome::passed;
  std::string message; // the one-line reason of a failure or skip
  std::string details; // the body of a failure
  double seconds = 0;
  std::vector<std::pair<std::string, std::string>> properties; // the result's figures
};

struct JunitSuite {
  std::string name;
  std::vector<std::pair<std::string, std::string>> properties; // <properties> of the suite
  std::vector<JunitCase> cases;
};

// Text safe inside an XML attribute (or element content, which keeps its line breaks):
// markup escaped, control characters XML 1.0 does not allow replaced by '?'.
std::string xml_escape(const std::string& text, bool attribute = true);

void write_junit(std::ostream& out, const std::vector<JunitSuite>& suites);

// A check or explore run as one suite: violated fails, incomplete is skipped.
JunitSuite junit_suite(const ModelRun& run, TraceMode trace);

} // namespace cli
