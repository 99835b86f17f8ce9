#pragma once
// A list of at most N values held in place, for model code that loads a queue, a buffer
// or a set out of a state, changes it and stores it back at every step: no allocation
// (the explorer calls effects millions of times a second). Going past N is a logic error
// of the model (it throws): a model checks its own bound before it adds, and records the
// bound met instead (as vn-emulation's Bound does).

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <stdexcept>

namespace tioa {

template <class T, std::size_t N> class FixedList {
public:
  FixedList() = default;
  FixedList(std::initializer_list<T> values) {
    for (const T& v : values)
      push_back(v);
  }

  static constexpr std::size_t capacity() { return N; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == N; }

  T* begin() { return items_.data(); }
  T* end() { return items_.data() + size_; }
  const T* begin() const { return items_.data(); }
  const T* end() const { return items_.data() + size_; }
  T& operator[](std::size_t i) { return items_[i]; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  T& front() { return items_[0]; }
  const T& front() const { return items_[0]; }

  void push_back(const T& value) {
    if (size_ == N)
      throw std::logic_error("FixedList: more than its capacity");
    items_[size_++] = value;
  }
  // Removes the element at `at`, keeping the order of the others.
  void erase(T* at) {
    std::move(at + 1, end(), at);
    --size_;
    items_[size_] = T{};
  }
  // Keeps the first n elements (n <= size()).
  void truncate(std::size_t n) {
    while (size_ > n)
      items_[--size_] = T{};
  }
  void clear() { truncate(0); }

  // Sorts by `less`, stably (an insertion sort: the lists are short; std::sort over a few
  // places makes GCC 12 warn of bounds it cannot see, -Warray-bounds).
  template <class Less> void sort(Less less) {
    for (std::size_t i = 1; i < size_; ++i) {
      T moving = std::move(items_[i]);
      std::size_t j = i;
      for (; j > 0 && less(moving, items_[j - 1]); --j)
        items_[j] = std::move(items_[j - 1]);
      items_[j] = std::move(moving);
    }
  }

private:
  std::array<T, N> items_{};
  std::size_t size_ = 0;
};

} // namespace tioa
