#pragma once
// Text helpers shared by the layers' reports.

#include <string>
#include <vector>

namespace support {

// The parts with `separator` between them: join({"a", "b"}) == "a, b".
inline std::string join(const std::vector<std::string>& parts,
                        const std::string& separator = ", ") {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i ? separator : "") + parts[i];
  return out;
}

// `text` for one line of an error message: control characters and bytes that are not part
// of valid UTF-8 as \xHH, so that a name or a line quoted from a binary file stays readable
// (UTF-8 text, "données", is kept as it is).
inline std::string printable(const std::string& text) {
  constexpr const char* digits = "0123456789abcdef";
  const auto escape = [&](std::string& to, unsigned char c) {
    to += "\\x";
    to += digits[c >> 4];
    to += digits[c & 0xf];
  };
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if (c < 0x20 || c == 0x7f)
        escape(out, c);
      else
        out += static_cast<char>(c);
      ++i;
      continue;
    }
    // A UTF-8 sequence: a lead byte 110xxxxx, 1110xxxx or 11110xxx and its continuations.
    const std::size_t length = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 ? 2 : 0;
    bool valid = length > 0 && c < 0xf5 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    if (valid) {
      out.append(text, i, length);
      i += length;
    } else {
      escape(out, c);
      ++i;
    }
  }
  return out;
}

} // namespace support
