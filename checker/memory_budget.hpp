#pragma once
// The memory limit of a run, and how buffers grow within it.
//
// A buffer grows only when what is held plus the new buffer (the old one is alive while
// it is copied) stays within the limit, so the limit holds at every growth, not only
// between checks. The peak is the most held at once as the limit counts it.
//
// MemoryBudget is the run's: it asks `held` (the store, the parents, the edges, the
// discovery keys and the workers' buffers) whenever something grows. During the
// expansion of a level the store grows only at the growth gate, where the budget is
// asked while every worker waits; each worker's own buffers have an Allowance instead:
// an equal share of what is left, checked without asking anybody else.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "checker/mapped_memory.hpp"
#include "checker/options.hpp"

namespace checker {

// Bytes of the bigger buffer that making room for `more` elements in `v` allocates, 0 when
// there is room; grow() then allocates exactly that. A buffer at least doubles.
template <class T> std::size_t growth_bytes(const std::vector<T>& v, std::size_t more) {
  if (v.capacity() - v.size() >= more)
    return 0;
  return std::max({2 * v.capacity(), v.size() + more, std::size_t{64}}) * sizeof(T);
}
template <class T> void grow(std::vector<T>& v, std::size_t more) {
  if (v.capacity() - v.size() < more)
    v.reserve(std::max({2 * v.capacity(), v.size() + more, std::size_t{64}}));
}

// The process's resident memory in bytes (/proc/self/statm; 0 where it cannot be read).
// It does not allocate, so that the explorer's workers may ask it.
std::uint64_t resident_bytes();

// Whether the property holds more than its memory limit: the growth of the resident memory
// since it started, which counts what no budget sees (a model's memo, a family being built,
// the allocator's slack) besides what the explorations hold. False without a limit or a base.
bool resident_over_limit(const Limits& limits);

// The memory limit of the next run of a property: max_memory_bytes less what the property's
// earlier runs still hold (the growth of the resident memory since it started); 0 when there
// is no limit, and at least 1 byte (a run with nothing left stops on the memory limit at
// once).
std::uint64_t memory_left(const Limits& limits);

class MemoryBudget {
public:
  static constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();

  // `limit` 0 means none; `held` says what the run holds now.
  MemoryBudget(std::uint64_t limit, std::function<std::size_t()> held)
      : limit_(limit), held_(std::move(held)) {}

  std::size_t held() const { return held_(); }
  std::size_t peak() const { return peak_; }

  // Whether the run may grow by `growth` bytes; records the peak. A refusal is for good:
  // the run stops on the memory limit.
  bool fits(std::size_t growth) { return growth == 0 || fits_slow(growth); }

  // Room for `more` elements in `v` within the budget.
  template <class T> bool grow_within(std::vector<T>& v, std::size_t more) {
    if (!fits(growth_bytes(v, more)))
      return false;
    grow(v, more);
    return true;
  }
  // The same for a vector of mapped memory, which grows without a copy.
  template <class T> bool grow_within(MappedVector<T>& v, std::size_t more) {
    if (!fits(v.growth_bytes(more)))
      return false;
    v.grow(more);
    return true;
  }

  // Whether the run holds more than the limit now.
  bool exceeded() const { return limit_ && held() > limit_; }

  // Counts `bytes` held at once towards the peak.
  void note(std::size_t bytes) { peak_ = std::max(peak_, bytes); }

  // One of `parts` equal shares of what is left when `held` is held (unlimited without
  // a limit).
  std::size_t share_left(std::size_t held, std::size_t parts) const;

private:
  bool fits_slow(std::size_t growth);

  std::uint64_t limit_;
  std::function<std::size_t()> held_;
  std::size_t peak_ = 0;
};

// What one worker may hold while a level is expanded: its buffers when the level began
// plus its share of what was left. The growth it reached adds to the run's peak.
class Allowance {
public:
  // The level begins with the worker holding `held`; `share` as MemoryBudget::share_left.
  void begin_level(std::size_t held, std::size_t share) {
    if (share != MemoryBudget::unlimited)
      limit_ = held + share;
    start_ = peak_ = held;
  }
  // Whether the worker, holding `held`, may grow by `growth` bytes (0 included: a worker's
  // buffers for the state being expanded grow unchecked, and count here).
  bool fits(std::size_t held, std::size_t growth) {
    const std::size_t total = held + growth;
    if (total > limit_)
      return false;
    peak_ = std::max(peak_, total);
    return true;
  }
  // A new share while the level goes on (the store grew at the growth gate, taking from
  // what was left): the worker, holding `held`, may grow by `share` more.
  void reshare(std::size_t held, std::size_t share) {
    if (share != MemoryBudget::unlimited)
      limit_ = held + share;
  }
  // The most the worker held in this level beyond what it held when the level began.
  std::size_t level_growth() const { return peak_ - start_; }

private:
  std::size_t limit_ = MemoryBudget::unlimited;
  std::size_t start_ = 0, peak_ = 0;
};

} // namespace checker
