#pragma once
// Work splitting shared by the analysis algorithms. The grid is a stack of independent Z layers (thesis 4.2.1), so
// most analyses split over Z (or over rows for rays along Z); chunks are handed out dynamically because a model
// usually fills only part of the Z range and its layers differ in cost.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace vox::analysis_detail {

// Threads worth starting for `work` units of roughly equal cost (words, voxels): one below kMinWorkPerThread,
// because starting a thread costs about as much as scanning tens of thousands of words.
inline int threadsFor(int64_t work) {
  constexpr int64_t kMinWorkPerThread = int64_t(1) << 16;
  const int hw = std::max(1, int(std::thread::hardware_concurrency()));
  return int(std::clamp<int64_t>(work / kMinWorkPerThread, 1, hw));
}

// Calls f(thread_index, begin, end) for consecutive chunks of [begin, end), each at most `grain` long, on
// `threads` threads (the calling thread is one of them). thread_index < threads, so callers can keep per-thread
// accumulators without locking.
template <class F>
void parallelChunks(int64_t begin, int64_t end, int64_t grain, int threads, F&& f) {
  if (end <= begin) return;
  grain = std::max<int64_t>(grain, 1);
  const int64_t chunks = (end - begin + grain - 1) / grain;
  threads = int(std::clamp<int64_t>(threads, 1, chunks));
  if (threads == 1) {
    f(0, begin, end);
    return;
  }
  std::atomic<int64_t> next{0};
  auto worker = [&](int t) {
    for (;;) {
      const int64_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks) return;
      const int64_t b = begin + c * grain;
      f(t, b, std::min(end, b + grain));
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(size_t(threads) - 1);
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& th : pool) th.join();
}

}  // namespace vox::analysis_detail
