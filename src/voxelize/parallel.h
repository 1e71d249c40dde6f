#pragma once
// Small std::thread helpers for the voxelizer (internal).
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace vox::voxelize_detail {

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

// Calls f(thread, i) for every i in [0, n) (layers, or slabs of them) on `threads` threads.
template <class F>
void forLayers(int32_t n, int threads, F&& f) {
  threads = std::clamp(threads, 1, std::max(1, int(n)));
  std::atomic<int32_t> next{0};
  auto worker = [&](int t) {
    for (int32_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < n;) f(t, i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& th : pool) th.join();
}

}  // namespace vox::voxelize_detail
