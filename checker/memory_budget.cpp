#include "checker/memory_budget.hpp"

#include <unistd.h>

#include <fstream>

namespace checker {

std::uint64_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size = 0, resident = 0;
  if (!(statm >> size >> resident))
    return 0;
  const long page = sysconf(_SC_PAGESIZE);
  return resident * static_cast<std::uint64_t>(page > 0 ? page : 4096);
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
