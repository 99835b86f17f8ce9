#pragma once
// A one-line progress report on stderr, redrawn in place, shown only when stderr is a
// terminal and the run has lasted more than a second.

#include <chrono>
#include <cstdint>
#include <string>

namespace checker {

class Progress {
public:
  Progress(bool enabled, std::string task);
  ~Progress();
  void update(std::uint64_t states, std::uint64_t frontier, std::uint32_t depth);
  // Any other status ("time layer 3: zero-time closure, round 12, ..."), the same way.
  void show(const std::string& status);
  double elapsed() const;

private:
  bool due(); // enabled, past the first second, and 200 ms since the last line

  bool enabled_;
  bool shown_ = false;
  std::string task_;
  std::chrono::steady_clock::time_point start_, last_;
};

} // namespace checker
