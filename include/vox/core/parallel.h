#pragma once
// Work splitting shared by the voxelizer and the analyses (std::thread, the calling thread always one of the
// workers). The grid is a stack of independent Z layers (thesis 4.2.1), so most work splits over Z, or over rows.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace vox {

// Threads worth starting for `work` units of roughly equal cost (words, voxels): one below 65536 units each,
// because starting a thread costs about as much as scanning tens of thousands of words.
inline int threadsFor(int64_t work) {
  constexpr int64_t kMinWorkPerThread = int64_t(1) << 16;
  const int hw = std::max(1, int(std::thread::hardware_concurrency()));
  return int(std::clamp<int64_t>(work / kMinWorkPerThread, 1, hw));
}

// Calls f(thread_index, begin, end) for consecutive chunks of [begin, end), each at most `grain` long, handed out
// dynamically (a model fills only part of the Z range and its layers differ in cost) on `threads` threads.
// thread_index < threads, so callers can keep per-thread accumulators without locking.
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

// Calls f(thread, i) for every i in [0, n) (layers, or slabs of them), handed out one at a time.
template <class F>
void forLayers(int32_t n, int threads, F&& f) {
  parallelChunks(0, n, 1, threads, [&](int t, int64_t begin, int64_t end) {
    for (int64_t i = begin; i < end; ++i) f(t, int32_t(i));  // one layer a chunk, or all of them on one thread
  });
}

// Splits [0, n) into `threads` contiguous chunks in order and calls f(chunk, begin, end) for each, chunk 0 on the
// calling thread. Contiguous, ordered chunks let callers merge per-chunk results deterministically.
template <class F>
void forChunks(int64_t n, int threads, F&& f) {
  threads = int(std::clamp<int64_t>(threads, 1, std::max<int64_t>(n, 1)));
  auto bounds = [&](int t) { return n * t / threads; };
  if (threads == 1) {
    f(0, int64_t(0), n);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(size_t(threads) - 1);
  for (int t = 1; t < threads; ++t) pool.emplace_back([&, t] { f(t, bounds(t), bounds(t + 1)); });
  f(0, int64_t(0), bounds(1));
  for (auto& th : pool) th.join();
}

}  // namespace vox
