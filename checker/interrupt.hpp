#pragma once
// A request to stop, from outside the run (SIGINT, SIGTERM: the command line installs the
// handler, cli/app.cpp). Every loop that checks the time limit checks this flag at the
// same places (the workers every 1024 states, the end of each level, the legal-set
// enumeration, the simulation search), so a run stops within about a second and reports
// what it covered as incomplete ("interrupted").

#include <atomic>

namespace checker {

// The process-wide flag; lock-free, so that a signal handler may set it.
inline std::atomic<bool>& stop_requested() {
  static std::atomic<bool> flag{false};
  return flag;
}

inline bool interrupted() {
  return stop_requested().load(std::memory_order_relaxed);
}

} // namespace checker
