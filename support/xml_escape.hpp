#pragma once
// Text for XML: the JUnit reports, the SVG figures and the HTML pages (which the tests read
// as XML). The five characters XML reserves are escaped; in an attribute, newlines and tabs
// too; control characters that XML 1.0 does not allow become '?'.

#include <string>
#include <string_view>

namespace support {

inline std::string xml_escape(std::string_view text, bool attribute = false) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
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
      out += "&apos;";
      break;
    case '\n':
      out += attribute ? "&#10;" : "\n";
      break;
    case '\t':
      out += attribute ? "&#9;" : "\t";
      break;
    case '\r':
      out += "&#13;";
      break;
    default:
      out += (byte < 0x20 || byte == 0x7f) ? '?' : c;
    }
  }
  return out;
}

} // namespace support
