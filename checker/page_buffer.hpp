#pragma once
// A zero-filled buffer of words straight from the kernel (mmap), asking for transparent
// huge pages: the hash table is read at random, and with 4 KiB pages nearly every
// lookup in a large table also misses the TLB.

#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>

#include <sys/mman.h>

namespace checker {

class PageBuffer {
public:
  PageBuffer() = default;
  explicit PageBuffer(std::size_t words) : bytes_(words * sizeof(std::uint64_t)) {
    if (bytes_ == 0)
      return;
    void* memory =
        mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED)
      throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(memory, bytes_, MADV_HUGEPAGE);
#endif
    data_ = static_cast<std::uint64_t*>(memory);
  }
  ~PageBuffer() {
    if (data_)
      munmap(data_, bytes_);
  }
  PageBuffer(const PageBuffer&) = delete;
  PageBuffer& operator=(const PageBuffer&) = delete;
  PageBuffer(PageBuffer&& other) noexcept {
    swap(other);
  }
  PageBuffer& operator=(PageBuffer&& other) noexcept {
    swap(other);
    return *this;
  }
  void swap(PageBuffer& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(bytes_, other.bytes_);
  }

  std::uint64_t* data() {
    return data_;
  }
  const std::uint64_t* data() const {
    return data_;
  }
  std::size_t bytes() const {
    return bytes_;
  }

private:
  std::uint64_t* data_ = nullptr;
  std::size_t bytes_ = 0;
};

} // namespace checker
