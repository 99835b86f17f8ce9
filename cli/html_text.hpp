#pragma once
// Text for an HTML page that is also well-formed XML (the pages of --html are checked as
// XML by the tests): the five characters that XML reserves, escaped.

#include <string>
#include <string_view>

namespace cli {

inline std::string html_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&#39;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

} // namespace cli
