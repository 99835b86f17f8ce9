#pragma once
// The store grows while nobody uses it. The workers of a level insert into the store
// concurrently; when it is out of room, a worker asks for growth and every worker stops
// at its next checkpoint (before each insertion); the last one to arrive grows the store
// (or finds the memory limit in the way and stops the level), then all go on. A worker
// that is done with its chunks leaves, so the others never wait for it.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>

namespace checker {

class GrowthGate {
public:
  // `grow` makes room and returns false when the memory limit does not allow it, which
  // stops the level. It runs on one thread while all the others wait.
  GrowthGate(std::size_t workers, std::function<bool()> grow)
      : active_(workers), grow_(std::move(grow)) {}

  // A worker asks for growth (then waits at checkpoint()).
  void request() { requested_.store(true, std::memory_order_release); }
  // What growing threw, if it did (the level stopped then).
  std::exception_ptr error() const { return error_; }
  bool stopped() const { return stopped_.load(std::memory_order_relaxed); }
  // Stops the level: every worker's next checkpoint says so.
  void stop() { stopped_.store(true, std::memory_order_relaxed); }

  // Between two insertions: waits while the store grows. False when the level stops.
  bool checkpoint() {
    if (requested_.load(std::memory_order_acquire))
      wait();
    return !stopped();
  }

  // A worker is done with its chunks (or failed).
  void leave() {
    std::unique_lock lock(mutex_);
    --active_;
    if (requested_.load(std::memory_order_relaxed) && waiting_ == active_)
      grow_now();
  }

private:
  void wait() {
    std::unique_lock lock(mutex_);
    if (!requested_.load(std::memory_order_relaxed))
      return;
    if (++waiting_ == active_) {
      grow_now();
      return;
    }
    const std::size_t round = round_;
    arrived_.wait(lock, [&] { return round_ != round; });
  }
  // With the mutex held and every active worker waiting.
  void grow_now() {
    bool grown = false;
    try {
      grown = grow_();
    } catch (...) {
      error_ = std::current_exception();
    }
    if (!grown)
      stop();
    requested_.store(false, std::memory_order_release);
    waiting_ = 0;
    ++round_;
    arrived_.notify_all();
  }

  std::mutex mutex_;
  std::condition_variable arrived_;
  std::atomic<bool> requested_{false};
  std::atomic<bool> stopped_{false};
  std::size_t active_;
  std::size_t waiting_ = 0;
  std::size_t round_ = 0;
  std::function<bool()> grow_;
  std::exception_ptr error_;
};

} // namespace checker
