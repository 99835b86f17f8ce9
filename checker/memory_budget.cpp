#include "checker/memory_budget.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>

namespace checker {

std::uint64_t resident_bytes() {
  // "size resident shared text lib data dt", in pages.
  const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    return 0;
  char text[128];
  const ssize_t got = ::read(fd, text, sizeof text - 1);
  ::close(fd);
  if (got <= 0)
    return 0;
  text[got] = '\0';
  char* end = nullptr;
  std::strtoull(text, &end, 10); // size
  const char* resident_text = end;
  const std::uint64_t resident = std::strtoull(resident_text, &end, 10);
  if (end == resident_text)
    return 0;
  const long page = sysconf(_SC_PAGESIZE);
  return resident * static_cast<std::uint64_t>(page > 0 ? page : 4096);
}

bool resident_over_limit(const Limits& limits) {
  if (limits.max_memory_bytes == 0 || limits.resident_base == 0)
    return false;
  const std::uint64_t now = resident_bytes();
  return now > limits.resident_base && now - limits.resident_base > limits.max_memory_bytes;
}

std::uint64_t memory_left(const Limits& limits) {
  if (limits.max_memory_bytes == 0)
    return 0;
  if (limits.resident_base == 0)
    return limits.max_memory_bytes;
  const std::uint64_t now = resident_bytes();
  const std::uint64_t held = now > limits.resident_base ? now - limits.resident_base : 0;
  return held < limits.max_memory_bytes ? limits.max_memory_bytes - held : 1;
}

bool MemoryBudget::fits_slow(std::size_t growth) {
  const std::size_t total = held() + growth;
  if (limit_ && total > limit_)
    return false;
  note(total);
  return true;
}

std::size_t MemoryBudget::share_left(std::size_t held, std::size_t parts) const {
  if (!limit_)
    return unlimited;
  const std::size_t left = held < limit_ ? limit_ - held : 0;
  return left / parts;
}

} // namespace checker
