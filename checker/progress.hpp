#pragma once
// A one-line progress report on stderr, redrawn in place, shown only when stderr is a
// terminal and the run has lasted more than a second.

#include <chrono>
#include <string>

namespace checker {

class Progress {
public:
  Progress(bool enabled, std::string task);
  ~Progress();
  void update(std::uint64_t states, std::uint64_t frontier, std::uint32_t depth);
  double elapsed() const;

private:
  bool enabled_;
  bool shown_ = false;
  std::string task_;
  std::chrono::steady_clock::time_point start_, last_;
};

} // namespace checker
