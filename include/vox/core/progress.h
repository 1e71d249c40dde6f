#pragma once
// Progress and cancellation for long operations (after OpenVDB's interrupter): the callee calls the callback with
// the fraction done in [0, 1]; the callback returns false to ask it to stop, and the callee then returns an Error
// with ErrorCode::kCancelled. An empty callback means "no progress reporting". Callbacks may be called from
// worker threads, but never concurrently (the callee serialises them).
#include <functional>

namespace vox {

using ProgressFn = std::function<bool(double fraction)>;

}  // namespace vox
