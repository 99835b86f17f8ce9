#pragma once
// Reading a small text file a user names (a scenario, a round configuration): the whole of
// it, or one clear reason why not. A directory, a device such as /dev/zero, a file larger
// than the limit, a read error, or a NUL byte (a binary file) is refused before anything
// parses it, so that no input hangs the tool or is half read.

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <string>

#include "support/text.hpp"

namespace support {

// Throws std::invalid_argument when `text` holds a NUL byte (a binary file, not a text).
inline void require_text(const std::string& text, const std::string& name) {
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw std::invalid_argument(printable(name) + ": holds a NUL byte at offset " +
                                std::to_string(nul) + ": not a text file");
}

// All of `in` (standard input), at most max_bytes of it; throws std::invalid_argument as
// read_text_file does.
inline std::string read_text_stream(std::istream& in, const std::string& name,
                                    std::size_t max_bytes) {
  std::string text;
  char buffer[4096];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      throw std::invalid_argument(printable(name) + ": larger than " + std::to_string(max_bytes) +
                                  " bytes: not one of ours");
  }
  if (in.bad())
    throw std::invalid_argument(printable(name) + ": read error");
  require_text(text, name);
  return text;
}

// The contents of the regular file `path`; throws std::invalid_argument saying what is
// wrong ("<path>: not a regular file", "... is larger than 1048576 bytes", "... holds a NUL
// byte at offset 12: not a text file", or the system's reason it cannot be read).
inline std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  const std::string name = printable(path);
  if (path.empty())
    throw std::invalid_argument("an empty file name");
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error)
    throw std::invalid_argument(name + ": " + error.message());
  if (std::filesystem::is_directory(status))
    throw std::invalid_argument(name + ": is a directory, not a file");
  if (!std::filesystem::is_regular_file(status))
    throw std::invalid_argument(name + ": not a regular file");
  const auto size = std::filesystem::file_size(path, error);
  if (!error && size > max_bytes)
    throw std::invalid_argument(name + ": " + std::to_string(size) + " bytes, larger than " +
                                std::to_string(max_bytes) + ": not one of ours");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::invalid_argument(name + ": cannot open: " + std::strerror(errno));
  return read_text_stream(in, path, max_bytes);
}

} // namespace support
