#pragma once
// Reading a text file of one statement a line (a path-reservation scenario, a curve of
// mc-round): what every such reader shares. A reader throws LineError for what is wrong
// with one line, and its caller adds the file and the line number, so that every error is
// one line "<file>:<line>: <what>".

#include <algorithm>
#include <istream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace support {

// What is wrong with one line.
struct LineError {
  std::string what;
};

// The text without leading and trailing blanks (spaces, tabs, a carriage return).
inline std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// The words of the text, split at blanks.
inline std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string word; in >> word;)
    out.push_back(word);
  return out;
}

// A statement that may appear once: `seen` keeps the line of the first; a second is a
// LineError naming it.
inline void once(std::optional<int>& seen, int line, const std::string& keyword) {
  if (seen)
    throw LineError{"a second " + keyword + " (the first is on line " + std::to_string(*seen) +
                    ")"};
  seen = line;
}

// Calls statement(text, line) for every line of `in` that holds something once a '#'
// comment and the blanks around it are taken away; a LineError it throws becomes one
// std::invalid_argument "<source>:<line>: <what>", and so does a read error. Returns
// "<source>:<last line>: ", where a reader says what is missing at the end.
template <class Statement>
std::string for_each_statement(std::istream& in, const std::string& source, Statement statement) {
  int line = 0;
  for (std::string text; std::getline(in, text);) {
    ++line;
    text = trim(text.substr(0, text.find('#')));
    if (text.empty())
      continue;
    try {
      statement(text, line);
    } catch (const LineError& e) {
      throw std::invalid_argument(source + ":" + std::to_string(line) + ": " + e.what);
    }
  }
  if (in.bad())
    throw std::invalid_argument(source + ": cannot read");
  return source + ":" + std::to_string(std::max(line, 1)) + ": ";
}

} // namespace support
