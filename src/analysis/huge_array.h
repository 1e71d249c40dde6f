#pragma once
// Zeroed arrays on 2 MiB pages where the kernel gives them, for the analyses that read memory at scattered places.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vox::analysis_detail {

// Zeroed values on memory the kernel is asked to back with 2 MiB pages where it can (Linux, transparent huge pages
// on "madvise"): for arrays read at scattered places, where with 4 KiB pages most reads would miss the address
// translation caches as well as the data caches (a ball's walk reads packed brick words all over its thread's
// array, 18 MB at first at R = 1000; the containment test reads the lattice table, 44 MB there).
// Asks the kernel to back [p, p + bytes) with 2 MiB pages where it can (the whole 2 MiB pages inside it), before the
// memory is first written: for a vector reserved, then filled.
inline void adviseHugePages([[maybe_unused]] void* p, [[maybe_unused]] size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kHuge = uintptr_t(2) << 20;
  const uintptr_t b = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) / kHuge * kHuge;
  const uintptr_t e = (reinterpret_cast<uintptr_t>(p) + bytes) / kHuge * kHuge;
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);  // a hint
#endif
}

template <class T>
class HugeArray {
 public:
  explicit HugeArray(size_t count) : count_(count) {
    constexpr size_t kHuge = size_t(2) << 20;
    const size_t bytes = std::max<size_t>((count * sizeof(T) + kHuge - 1) / kHuge * kHuge, kHuge);
    values_.reset(static_cast<T*>(std::aligned_alloc(kHuge, bytes)));
    if (!values_) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(values_.get(), bytes, MADV_HUGEPAGE);  // a hint: 4 KiB pages where it is refused
#endif
    std::memset(values_.get(), 0, count * sizeof(T));
  }
  T& operator[](size_t i) { return values_[i]; }
  const T& operator[](size_t i) const { return values_[i]; }
  T* data() { return values_.get(); }
  const T* data() const { return values_.get(); }
  size_t size() const { return count_; }

 private:
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  size_t count_;
  std::unique_ptr<T[], Free> values_;
};

}  // namespace vox::analysis_detail
