// A std::allocator for large arrays that are read at random (training vectors, the k-means++
// arena). On Linux, blocks of 4 MiB and more are aligned to 2 MiB and marked for transparent
// huge pages: a random read then rarely misses the TLB, and the kernel maps 2 MiB per fault
// instead of 4 KiB, which matters most under virtualization. Elsewhere it is std::allocator.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace voltree {

template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(size_t count) {
    const size_t bytes = count * sizeof(T);
    if (!IsLarge(bytes)) return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
    static_assert(alignof(T) <= kHugePage);
    void* block = std::aligned_alloc(kHugePage, RoundUp(bytes));
    if (!block) throw std::bad_alloc();
#if defined(__linux__)
    madvise(block, RoundUp(bytes), MADV_HUGEPAGE);  // a hint: ignored where THP is off
#endif
    return static_cast<T*>(block);
  }

  void deallocate(T* block, size_t count) {
    if (IsLarge(count * sizeof(T))) {
      std::free(block);
    } else {
      ::operator delete(block, std::align_val_t(alignof(T)));
    }
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }

 private:
  static constexpr size_t kHugePage = size_t(2) << 20;
  static bool IsLarge(size_t bytes) { return bytes >= 2 * kHugePage; }
  static size_t RoundUp(size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }
};

// A vector whose large buffers get huge pages.
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace voltree
