#pragma once
// Work between two levels that every worker thread can share (the store's table refilled
// when it grows, a level renumbered): body(begin, end) over [0, n) cut into `threads`
// contiguous ranges, one per thread, the calling thread taking the first. Below
// `min_per_thread` items a thread, fewer threads (one: the calling thread alone). The
// bodies must not throw.

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

namespace checker {

template <class Body>
void parallel_for(std::uint32_t threads, std::uint64_t n, Body&& body,
                  std::uint64_t min_per_thread = std::uint64_t{1} << 16) {
  const std::uint64_t used =
      std::clamp<std::uint64_t>(n / std::max<std::uint64_t>(min_per_thread, 1), 1, threads);
  if (used <= 1) {
    body(std::uint64_t{0}, n);
    return;
  }
  auto cut = [&](std::uint64_t t) { return n * t / used; };
  std::vector<std::thread> helpers;
  helpers.reserve(used - 1);
  for (std::uint64_t t = 1; t < used; ++t)
    helpers.emplace_back([&, t] { body(cut(t), cut(t + 1)); });
  body(cut(0), cut(1));
  for (auto& helper : helpers)
    helper.join();
}

} // namespace checker
