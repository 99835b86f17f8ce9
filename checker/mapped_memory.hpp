#pragma once
// Memory straight from the kernel for the explorer's big arrays (the store's table and
// arena, the parents):
//   MappedArray<T>   zero-filled elements from mmap; it grows with mremap, which moves the
//                    pages instead of copying them, so a growing array is never held twice.
//                    Growing may move it: nobody may read it meanwhile.
//   MappedVector<T>  a vector on a MappedArray, for the arrays indexed by state id.
// Large arrays ask for transparent huge pages (the table is read at random, and with
// 4 KiB pages nearly every lookup in a large table also misses the TLB); small ones do
// not, so the many small explorations of a proof do not each fault in 2 MiB pages.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/mman.h>

namespace checker {

// Arrays of at least this size ask for huge pages.
inline constexpr std::size_t huge_page_threshold = std::size_t{8} << 20;

template <class T> class MappedArray {
  static_assert(std::is_trivially_copyable_v<T>);

public:
  MappedArray() = default;
  explicit MappedArray(std::size_t elements) { reserve(elements); }
  ~MappedArray() { release(); }
  MappedArray(const MappedArray&) = delete;
  MappedArray& operator=(const MappedArray&) = delete;
  MappedArray(MappedArray&& other) noexcept { swap(other); }
  MappedArray& operator=(MappedArray&& other) noexcept {
    swap(other);
    return *this;
  }
  void swap(MappedArray& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(bytes_, other.bytes_);
  }

  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  // Elements mapped (zero until written).
  std::size_t capacity() const { return bytes_ / sizeof(T); }
  std::size_t bytes() const { return bytes_; }

  // Room for `elements` in all, keeping the contents: the mapping at least doubles. The
  // array may move.
  void reserve(std::size_t elements) {
    if (elements <= capacity())
      return;
    const std::size_t page = 4096;
    std::size_t bytes = std::max(elements * sizeof(T), 2 * bytes_);
    bytes = (bytes + page - 1) / page * page;
    void* memory = bytes_ == 0 ? mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                                      MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)
                               : mremap(data_, bytes_, bytes, MREMAP_MAYMOVE);
    if (memory == MAP_FAILED)
      throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    if (bytes >= huge_page_threshold)
      madvise(memory, bytes, MADV_HUGEPAGE);
#endif
    data_ = static_cast<T*>(memory);
    bytes_ = bytes;
  }

  // Gives the memory back; the array is empty.
  void release() {
    if (data_)
      munmap(data_, bytes_);
    data_ = nullptr;
    bytes_ = 0;
  }

private:
  T* data_ = nullptr;
  std::size_t bytes_ = 0;
};

// A vector that never holds two copies of itself. capacity() is what it counts as held:
// it grows in steps of an eighth (only the pages written are resident, and the mapping
// behind it doubles), so the memory limit sees the growth a few times per doubling.
template <class T> class MappedVector {
public:
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t capacity() const { return capacity_; }
  T* data() { return array_.data(); }
  const T* data() const { return array_.data(); }
  T& operator[](std::size_t i) { return array_[i]; }
  const T& operator[](std::size_t i) const { return array_[i]; }
  const T* begin() const { return array_.data(); }
  const T* end() const { return array_.data() + size_; }
  T& back() { return array_[size_ - 1]; }

  // Bytes that making room for `more` elements adds to capacity() (0 when there is room):
  // unlike a std::vector's, the old buffer is not held besides the new one.
  std::size_t growth_bytes(std::size_t more) const {
    return size_ + more <= capacity_ ? 0 : (grown(size_ + more) - capacity_) * sizeof(T);
  }
  void grow(std::size_t more) {
    if (size_ + more <= capacity_)
      return;
    capacity_ = grown(size_ + more);
    array_.reserve(capacity_);
  }
  void push_back(const T& value) {
    grow(1);
    array_[size_++] = value;
  }
  // n elements: the first size() kept; the others hold what the memory held (zero where
  // never written).
  void resize(std::size_t n) {
    if (n > size_)
      grow(n - size_);
    size_ = n;
  }
  // Keeps the first `n` elements (n <= size()).
  void truncate(std::size_t n) { size_ = std::min(size_, n); }
  void clear() { size_ = 0; }

  bool operator==(const MappedVector& other) const {
    return std::equal(begin(), end(), other.begin(), other.end());
  }
  bool operator==(const std::vector<T>& other) const {
    return std::equal(begin(), end(), other.begin(), other.end());
  }

private:
  std::size_t grown(std::size_t needed) const {
    return std::max({needed, capacity_ + capacity_ / 8, 4096 / sizeof(T)});
  }

  MappedArray<T> array_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

} // namespace checker
