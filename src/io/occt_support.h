#pragma once
// What the Open CASCADE readers and the mesher share (src/io/cad_read.cpp, cad_tessellate.cpp): a lock around the
// data-exchange readers, OCCT's messages caught instead of printed, and voxmod's ProgressFn as an OCCT progress
// indicator. Only .cpp files of io include this header (it pulls in OCCT's).
#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Standard_Failure.hxx>

#include "vox/core/progress.h"

namespace vox::io::occt {

// Held while a STEP or IGES file is read and transferred: the readers keep their settings (Interface_Static) and
// controllers in process-wide state. While held, OCCT's messages of gravity Fail and above are collected for it.
class ReaderLock {
 public:
  ReaderLock();
  ~ReaderLock();
  ReaderLock(const ReaderLock&) = delete;
  ReaderLock& operator=(const ReaderLock&) = delete;
  // The failure messages OCCT sent while the lock was held, oldest first (at most a few, each trimmed).
  std::vector<std::string> failures() const;

 private:
  std::unique_lock<std::mutex> lock_;
};

// Replaces OCCT's default message printers (which write to stdout) by voxmod's collector, once per process: library
// code never prints.
void silenceMessages();

// Reports OCCT's progress (its position in [0, 1]) as from + (to - from) * position through `progress`; a false
// answer makes UserBreak() true, which OCCT's algorithms poll to stop.
class ProgressBridge : public Message_ProgressIndicator {
 public:
  ProgressBridge(const ProgressFn& progress, double from, double to) : progress_(progress), from_(from), to_(to) {}
  Standard_Boolean UserBreak() override { return cancelled_.load(std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

 protected:
  // OCCT calls Show under the indicator's own mutex, so progress_ is never called concurrently.
  void Show(const Message_ProgressScope& scope, const Standard_Boolean force) override;

 private:
  const ProgressFn& progress_;
  double from_, to_;
  std::atomic<bool> cancelled_{false};
};

// "what OCCT said" from an exception, for messages.
std::string failureText(const Standard_Failure& failure);

}  // namespace vox::io::occt
