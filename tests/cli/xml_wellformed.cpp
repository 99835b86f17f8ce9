// Exit 0 when the file is well-formed XML for the subset a JUnit report uses, else 1 with
// the reason: an optional <?xml ...?> declaration, an optional <!DOCTYPE ...>, then one root
// element (it must be <testsuites>, or the ROOT given: html for the --html pages); elements
// properly nested; attribute values in quotes without '<'; no bare '<' or '&' in text; only the
// five predefined entities and numeric references; no control characters other than tab, newline
// and carriage return.

#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Parser {
  std::string text;
  std::size_t at = 0;
  std::string error;
  std::string root = "testsuites";

  bool fail(const std::string& why) {
    if (error.empty())
      error = "offset " + std::to_string(at) + ": " + why;
    return false;
  }
  bool done() const { return at >= text.size(); }
  static bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
           c == ':' || static_cast<unsigned char>(c) >= 0x80;
  }
  void skip_space() {
    while (!done() && std::isspace(static_cast<unsigned char>(text[at])))
      ++at;
  }
  std::string name() {
    const std::size_t start = at;
    while (!done() && name_char(text[at]))
      ++at;
    return text.substr(start, at - start);
  }
  // A reference after '&': &amp; &lt; &gt; &quot; &apos; &#N; &#xN;
  bool reference() {
    const std::size_t semicolon = text.find(';', at);
    if (semicolon == std::string::npos || semicolon - at > 10)
      return fail("'&' that starts no reference");
    const std::string ref = text.substr(at + 1, semicolon - at - 1);
    const bool numeric =
        ref.size() > 1 && ref[0] == '#' &&
        ref.find_first_not_of(ref[1] == 'x' ? "0123456789abcdefABCDEF" : "0123456789",
                              ref[1] == 'x' ? 2 : 1) == std::string::npos;
    if (!numeric && ref != "amp" && ref != "lt" && ref != "gt" && ref != "quot" && ref != "apos")
      return fail("unknown entity &" + ref + ";");
    at = semicolon + 1;
    return true;
  }
  bool character_ok(char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte >= 0x20 || c == '\t' || c == '\n' || c == '\r';
  }
  bool attribute_value() {
    const char quote = text[at];
    if (quote != '"' && quote != '\'')
      return fail("attribute value without quotes");
    ++at;
    while (!done() && text[at] != quote) {
      if (text[at] == '<')
        return fail("'<' inside an attribute value");
      if (!character_ok(text[at]))
        return fail("control character in an attribute value");
      if (text[at] == '&') {
        if (!reference())
          return false;
      } else {
        ++at;
      }
    }
    if (done())
      return fail("unterminated attribute value");
    ++at;
    return true;
  }
  bool document() {
    if (text.compare(0, 5, "<?xml") == 0) {
      const std::size_t end = text.find("?>");
      if (end == std::string::npos)
        return fail("unterminated XML declaration");
      at = end + 2;
    }
    skip_space();
    if (text.compare(at, 9, "<!DOCTYPE") == 0) {
      const std::size_t end = text.find('>', at);
      if (end == std::string::npos)
        return fail("unterminated DOCTYPE");
      at = end + 1;
      skip_space();
    }
    std::vector<std::string> open;
    bool root_seen = false;
    while (!done()) {
      if (text[at] == '<') {
        ++at;
        if (!done() && text[at] == '/') {
          ++at;
          const std::string closing = name();
          skip_space();
          if (done() || text[at] != '>')
            return fail("malformed end tag");
          ++at;
          if (open.empty() || open.back() != closing)
            return fail("end tag </" + closing + "> does not match");
          open.pop_back();
        } else {
          const std::string element = name();
          if (element.empty())
            return fail("'<' that starts no tag");
          if (open.empty()) {
            if (root_seen)
              return fail("a second root element <" + element + ">");
            if (element != root)
              return fail("the root is <" + element + ">, not <" + root + ">");
            root_seen = true;
          }
          std::vector<std::string> attributes;
          while (true) {
            const std::size_t before = at;
            skip_space();
            if (done())
              return fail("unterminated tag <" + element + ">");
            if (text[at] == '/' || text[at] == '>')
              break;
            if (at == before)
              return fail("no space before an attribute");
            const std::string attribute = name();
            if (attribute.empty())
              return fail("malformed attribute in <" + element + ">");
            for (const auto& a : attributes)
              if (a == attribute)
                return fail("attribute " + attribute + " given twice");
            attributes.push_back(attribute);
            skip_space();
            if (done() || text[at] != '=')
              return fail("attribute " + attribute + " without '='");
            ++at;
            skip_space();
            if (!attribute_value())
              return false;
          }
          if (text[at] == '/') {
            if (++at >= text.size() || text[at] != '>')
              return fail("malformed empty-element tag");
            ++at;
          } else {
            ++at;
            open.push_back(element);
          }
        }
      } else if (text[at] == '&') {
        if (!reference())
          return false;
      } else {
        if (!character_ok(text[at]))
          return fail("control character in text");
        if (open.empty() && !std::isspace(static_cast<unsigned char>(text[at])))
          return fail("text outside the root element");
        ++at;
      }
    }
    if (!open.empty())
      return fail("element <" + open.back() + "> is not closed");
    if (!root_seen)
      return fail("no root element");
    return true;
  }
};

} // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::cerr << "usage: cli_xml_wellformed FILE [ROOT]\n";
    return 2;
  }
  std::ifstream file(argv[1], std::ios::binary);
  if (!file) {
    std::cerr << "cannot read " << argv[1] << '\n';
    return 1;
  }
  std::ostringstream content;
  content << file.rdbuf();
  Parser parser;
  parser.text = content.str();
  if (argc == 3)
    parser.root = argv[2];
  if (!parser.document()) {
    std::cerr << "malformed XML: " << parser.error << '\n';
    return 1;
  }
  return 0;
}
