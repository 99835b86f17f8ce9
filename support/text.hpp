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

} // namespace support
