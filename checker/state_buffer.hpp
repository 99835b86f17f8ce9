#pragma once
// A growable run of packed states that never shrinks: clear() keeps the memory, and
// appending copies words without initialising them first. A worker's level buffers.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "checker/state_store.hpp"

namespace checker {

class StateBuffer {
public:
  explicit StateBuffer(std::uint32_t words) : words_(words) {}
  void clear() { size_ = 0; }
  std::size_t size() const { return words_ ? size_ / words_ : 0; }
  void push(const Word* state) {
    if (size_ + words_ > storage_.size())
      storage_.resize(grown(size_ + words_));
    for (std::uint32_t i = 0; i < words_; ++i)
      storage_[size_ + i] = state[i];
    size_ += words_;
  }
  const Word* operator[](std::size_t index) const { return storage_.data() + index * words_; }
  std::size_t bytes() const { return storage_.capacity() * sizeof(Word); }
  // As growth_bytes() and grow() for vectors (memory_budget.hpp), counted in states.
  std::size_t growth_bytes(std::size_t more) const {
    const std::size_t needed = size_ + more * words_;
    return needed <= storage_.size() ? 0 : grown(needed) * sizeof(Word);
  }
  void grow(std::size_t more) {
    const std::size_t needed = size_ + more * words_;
    if (needed > storage_.size())
      storage_.resize(grown(needed));
  }

private:
  // Resizing to this allocates exactly this many words (the buffer at least doubles).
  std::size_t grown(std::size_t needed) const {
    return std::max({2 * storage_.size(), needed, std::size_t{64} * words_});
  }

  std::uint32_t words_;
  std::size_t size_ = 0; // in words
  std::vector<Word> storage_;
};

} // namespace checker
