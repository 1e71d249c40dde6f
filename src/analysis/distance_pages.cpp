// Which blocks of a distance field's memory go on 2 MiB pages, see analysis/distance_pages.h.
#include "analysis/distance_pages.h"

#include <algorithm>
#include <atomic>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "vox/core/bits.h"
#include "vox/core/parallel.h"

namespace vox::analysis_detail {

// Asks the kernel for 2 MiB pages over the blocks of the field's memory that the passes write most of, before anything
// is written (the advice applies to pages not yet touched). A page is written when it holds a voxel with a value
// (filled for a distance, empty for a clearance); pages left zero, the space about the part inside its box, are never
// faulted in on 4 KiB pages, but a 2 MiB page is resident whole. So the fullest blocks are advised first, down to the
// fill at which their unwritten pages would add more than kExtra of the written ones to the resident memory. An
// advised block costs one fault instead of up to 512, and the Z pass, which reads a row of every slice, one address
// translation instead of one per page (docs/performance.md, "Distance and thickness").
void adviseHugePages(const VoxelGrid& g, DistanceField& f, bool to_empty) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kPage = 4096, kHuge = uintptr_t(2) << 20;
  constexpr int64_t kPagesPerHuge = int64_t(kHuge / kPage);
  constexpr double kExtra = 1.0 / 6;
  const uintptr_t start = reinterpret_cast<uintptr_t>(f.data());
  const uintptr_t end = start + f.memoryBytes();
  const uintptr_t first_huge = (start + kHuge - 1) / kHuge * kHuge, last_huge = end / kHuge * kHuge;
  if (last_huge <= first_huge) return;
  const int64_t pages = int64_t((end - first_huge + kPage - 1) / kPage);
  std::vector<std::atomic<uint8_t>> written(static_cast<size_t>(pages));  // zeroed (value-initialised)
  const glm::ivec3 lo = f.boxMin();
  const Dims d = f.boxDims();
  parallelChunks(0, d.nz, 1, threadsFor(int64_t(d.ny) * d.nz * g.wordsPerRow()), [&](int, int64_t zb, int64_t ze) {
    for (int64_t zi = zb; zi < ze; ++zi) {
      for (int32_t yi = 0; yi < d.ny; ++yi) {
        const uint64_t* row = g.rowWords(lo.y + yi, lo.z + int32_t(zi));
        const DistanceField::Row r = f.row(yi, zi);
        const int64_t begin = int64_t(lo.x) + 1 + r.lo, stop = int64_t(lo.x) + 1 + r.hi;  // padded x of the row's span
        const uintptr_t out = start + uintptr_t((r.base + r.lo) * int64_t(sizeof(uint32_t)));
        for (int64_t xp = begin; xp < stop;) {
          const int64_t a = nextBit(row, xp, stop, to_empty);
          if (a >= stop) break;
          const int64_t b = nextBit(row, a, stop, !to_empty);
          const uintptr_t ba = out + uintptr_t(a - begin) * sizeof(uint32_t);
          const uintptr_t bb = out + uintptr_t(b - begin) * sizeof(uint32_t);
          for (uintptr_t pg = std::max(ba, first_huge) / kPage; pg * kPage < bb; ++pg) {
            written[size_t(pg - first_huge / kPage)].store(1, std::memory_order_relaxed);
          }
          xp = b;
        }
      }
    }
  });
  // Written pages per block; then the lowest count at which the blocks of that count and above hold at most kExtra of
  // the written pages' number in unwritten pages.
  const int64_t blocks = int64_t((last_huge - first_huge) / kHuge);
  std::vector<int32_t> count(size_t(blocks), 0);
  std::vector<int64_t> with(size_t(kPagesPerHuge) + 1, 0);  // blocks per count
  int64_t total = 0;
  for (int64_t b = 0; b < blocks; ++b) {
    int32_t n = 0;
    for (int64_t i = 0; i < kPagesPerHuge; ++i) {
      n += written[size_t(b * kPagesPerHuge + i)].load(std::memory_order_relaxed);
    }
    count[size_t(b)] = n;
    ++with[size_t(n)];
    total += n;
  }
  int64_t threshold = kPagesPerHuge + 1, extra = 0;
  while (threshold > 1) {
    const int64_t more = extra + with[size_t(threshold - 1)] * (kPagesPerHuge - (threshold - 1));
    if (more > int64_t(double(total) * kExtra)) break;
    extra = more;
    --threshold;
  }
  for (int64_t b = 0; b < blocks; ++b) {
    if (count[size_t(b)] >= threshold) {
      madvise(reinterpret_cast<void*>(first_huge + uintptr_t(b) * kHuge), kHuge, MADV_HUGEPAGE);  // a hint
    }
  }
#else
  (void)g, (void)f, (void)to_empty;
#endif
}

}  // namespace vox::analysis_detail
