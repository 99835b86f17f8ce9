#pragma once
// Text for an HTML page that is also well-formed XML (the pages of --html are checked as
// XML by the tests): the five characters that XML reserves, escaped.

#include <string>
#include <string_view>

#include "support/xml_escape.hpp"

namespace cli {

inline std::string html_text(std::string_view text) {
  return support::xml_escape(text);
}

} // namespace cli
