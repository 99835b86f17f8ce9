#pragma once
// A std::vector whose resize() and sized constructor leave new elements of a trivial type
// uninitialised instead of zeroing them: for buffers of millions of ids that are written
// in full right after (a level's renumbering), where the zeroing would be a serial pass
// over fresh pages before the parallel one that writes them.

#include <memory>
#include <utility>
#include <vector>

namespace checker {

template <class T> struct DefaultInitAllocator : std::allocator<T> {
  template <class U> struct rebind { using other = DefaultInitAllocator<U>; };
  DefaultInitAllocator() = default;
  template <class U> DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U> void construct(U* at) noexcept { ::new (static_cast<void*>(at)) U; }
  template <class U, class... Args> void construct(U* at, Args&&... args) {
    ::new (static_cast<void*>(at)) U(std::forward<Args>(args)...);
  }
};

template <class T> using UninitialisedVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace checker
