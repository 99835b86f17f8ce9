#include "cli/render_table.hpp"

#include "cli/html_text.hpp"

namespace cli {

namespace {

std::string value_text(const Json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

} // namespace

void write_state_table(std::ostream& out, const Json& state, const Json* previous) {
  out << "<table class=\"state\"><tr><th>variable</th><th>value</th></tr>\n";
  for (const auto& [name, value] : state.items()) {
    const bool changed = previous && (!previous->contains(name) || (*previous)[name] != value);
    out << "<tr" << (changed ? " class=\"changed\"" : "") << "><td>" << html_text(name)
        << "</td><td>" << html_text(value_text(value));
    if (changed && previous->contains(name))
      out << " <span class=\"was\">(was " << html_text(value_text((*previous)[name])) << ")</span>";
    out << "</td></tr>\n";
  }
  out << "</table>\n";
}

} // namespace cli
