#pragma once
// Progress from worker threads (vox/core/progress.h): calls to the callback are serialised, and once it asks to
// stop every worker sees cancelled() and winds down.
#include <algorithm>
#include <atomic>
#include <mutex>

#include "vox/core/progress.h"

namespace vox::analysis_detail {

class ProgressGate {
 public:
  explicit ProgressGate(const ProgressFn& fn) : fn_(fn) {}
  // Reports `fraction` (clamped to [0, 1]); false once the callback has asked to stop.
  bool report(double fraction) {
    if (cancelled_.load(std::memory_order_relaxed)) return false;
    if (!fn_) return true;
    std::lock_guard<std::mutex> lock(mutex_);
    if (cancelled_.load(std::memory_order_relaxed)) return false;
    // workers finish out of order: never report less than before
    last_ = std::max(last_, fraction < 0 ? 0.0 : (fraction > 1 ? 1.0 : fraction));
    if (!fn_(last_)) cancelled_.store(true);
    return !cancelled_.load();
  }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

 private:
  const ProgressFn& fn_;
  std::mutex mutex_;
  std::atomic<bool> cancelled_{false};
  double last_ = 0.0;  // guarded by mutex_
};

}  // namespace vox::analysis_detail
