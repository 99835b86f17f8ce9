#include "checker/memory_budget.hpp"

namespace checker {

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
