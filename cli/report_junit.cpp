#include "cli/report_junit.hpp"

#include "support/xml_escape.hpp"

#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "cli/report_text.hpp"
#include "cli/time_note.hpp"

namespace cli {

std::string xml_escape(const std::string& text, bool attribute) {
  return support::xml_escape(text, attribute);
}

namespace {

// <properties> (named values of a suite, or a case's figures), indented; nothing when empty.
void write_properties(std::ostream& out,
                      const std::vector<std::pair<std::string, std::string>>& properties,
                      const std::string& indent) {
  if (properties.empty())
    return;
  out << indent << "<properties>\n";
  for (const auto& [name, value] : properties)
    out << indent << "  <property name=\"" << xml_escape(name) << "\" value=\"" << xml_escape(value)
        << "\"/>\n";
  out << indent << "</properties>\n";
}

} // namespace

void write_junit(std::ostream& out, const std::vector<JunitSuite>& suites) {
  std::size_t total = 0, failures = 0, skipped = 0;
  double seconds = 0;
  for (const auto& suite : suites)
    for (const auto& c : suite.cases) {
      ++total;
      failures += c.outcome == JunitCase::Outcome::failed;
      skipped += c.outcome == JunitCase::Outcome::skipped;
      seconds += c.seconds;
    }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format(
      "<testsuites name=\"tioa-check\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"{}\" "
      "time=\"{:.3f}\">\n",
      total, failures, skipped, seconds);
  for (const auto& suite : suites) {
    std::size_t suite_failures = 0, suite_skipped = 0;
    double suite_seconds = 0;
    for (const auto& c : suite.cases) {
      suite_failures += c.outcome == JunitCase::Outcome::failed;
      suite_skipped += c.outcome == JunitCase::Outcome::skipped;
      suite_seconds += c.seconds;
    }
    out << fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" "
                       "skipped=\"{}\" time=\"{:.3f}\">\n",
                       xml_escape(suite.name), suite.cases.size(), suite_failures, suite_skipped,
                       suite_seconds);
    write_properties(out, suite.properties, "    ");
    for (const auto& c : suite.cases) {
      out << fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.3f}\"",
                         xml_escape(c.name), xml_escape(suite.name), c.seconds);
      if (c.outcome == JunitCase::Outcome::passed && c.properties.empty()) {
        out << "/>\n";
        continue;
      }
      out << ">\n";
      write_properties(out, c.properties, "      ");
      if (c.outcome == JunitCase::Outcome::failed)
        out << "      <failure message=\"" << xml_escape(c.message) << "\">"
            << xml_escape(c.details, false) << "</failure>\n";
      else if (c.outcome == JunitCase::Outcome::skipped)
        out << "      <skipped message=\"" << xml_escape(c.message) << "\"/>\n";
      out << "    </testcase>\n";
    }
    out << "  </testsuite>\n";
  }
  out << "</testsuites>\n";
}

JunitSuite junit_suite(const ModelRun& run, TraceMode trace) {
  JunitSuite suite;
  suite.name = run.model;
  for (const auto& [name, value] : run.params)
    suite.properties.emplace_back("param." + name, value.text());
  if (!run.variant.empty())
    suite.properties.emplace_back("variant", run.variant);
  if (!run.from.empty())
    suite.properties.emplace_back("from", run.from);
  if (!run.quantum.empty())
    suite.properties.emplace_back("time_note", time_note(run.quantum));
  for (const auto& r : run.results) {
    JunitCase c;
    c.name = r.name;
    c.seconds = r.seconds;
    c.message = r.message;
    c.properties = r.figures;
    if (r.verdict == checker::Verdict::violated) {
      c.outcome = JunitCase::Outcome::failed;
      std::ostringstream details;
      print_property_block(details, run, r, trace);
      c.details = details.str();
    } else if (r.verdict == checker::Verdict::incomplete) {
      c.outcome = JunitCase::Outcome::skipped;
    }
    suite.cases.push_back(std::move(c));
  }
  for (const std::string& name : run.not_run) {
    JunitCase c;
    c.name = name;
    c.outcome = JunitCase::Outcome::skipped;
    c.message = "not run: the run was interrupted (SIGINT or SIGTERM)";
    suite.cases.push_back(std::move(c));
  }
  return suite;
}

} // namespace cli
