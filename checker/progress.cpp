#include "checker/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace checker {

Progress::Progress(bool enabled, std::string task)
    : enabled_(enabled && isatty(fileno(stderr))), task_(std::move(task)),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() {
  if (shown_)
    std::fprintf(stderr, "\r\033[K");
}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool Progress::due() {
  if (!enabled_)
    return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(200))
    return false;
  last_ = now;
  shown_ = true;
  return true;
}

void Progress::show(const std::string& status) {
  if (!due())
    return;
  std::fprintf(stderr, "\r\033[K%s: %s, %.1f s", task_.c_str(), status.c_str(), elapsed());
  std::fflush(stderr);
}

void Progress::update(std::uint64_t states, std::uint64_t frontier, std::uint32_t depth) {
  if (!due())
    return;
  const double seconds = elapsed();
  std::fprintf(stderr, "\r\033[K%s: %llu states, frontier %llu, depth %u, %.1f s, %.2f M states/s",
               task_.c_str(), static_cast<unsigned long long>(states),
               static_cast<unsigned long long>(frontier), depth, seconds,
               static_cast<double>(states) / seconds / 1e6);
  std::fflush(stderr);
}

} // namespace checker
