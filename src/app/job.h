#pragma once
// Background work for the window: voxelizing, loading and the slower analyses run on a worker thread so the window
// keeps drawing (and Cancel keeps working) while they run. The worker gets its own copies of the inputs; VoxelGrid
// copies share their layers copy-on-write, so handing a grid to a worker costs a vector of pointers.
//
// Starting a job while another runs cancels the old one without waiting for it: its thread is retired and joined
// once it has noticed the cancel flag (or at exit), so a slow analysis that has no progress callback never blocks
// the window.
#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "vox/core/progress.h"
#include "vox/core/result.h"

namespace vox::app {

template <class T>
class Job {
 public:
  using Work = std::function<Result<T>(const ProgressFn& progress)>;

  Job() = default;
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;
  ~Job() {
    cancel();
    retired_.clear();  // jthread joins
  }

  // Runs `work` on a new thread. A job already running is cancelled and retired. `keeps_late_result`: work with an
  // effect outside the window (a file written) hands out what it did even when cancelled too late to stop it.
  void start(std::string label, Work work, bool keeps_late_result = false) {
    retire();
    label_ = std::move(label);
    keeps_late_result_ = keeps_late_result;
    state_ = std::make_shared<State>();
    auto state = state_;
    thread_ = std::jthread([state, work = std::move(work), label = label_] {
      const ProgressFn progress = [state](double fraction) {
        state->progress.store(fraction, std::memory_order_relaxed);
        return !state->cancel.load(std::memory_order_relaxed);
      };
      // An exception on the worker (memory it could not have, a fault) is the job's error: it never ends the process.
      try {
        state->result.emplace(work(progress));
      } catch (const std::bad_alloc&) {
        state->result.emplace(makeError(ErrorCode::kLimit, label + " needed more memory than this machine can give"));
      } catch (const std::exception& e) {
        state->result.emplace(makeError(ErrorCode::kInvalidArgument, label + " failed: " + e.what()));
      }
      state->done.store(true, std::memory_order_release);
    });
  }

  bool running() const { return state_ && !state_->done.load(std::memory_order_acquire); }
  // True from start() until take() has handed out the result.
  bool active() const { return state_ != nullptr; }
  double progress() const { return state_ ? state_->progress.load(std::memory_order_relaxed) : 0.0; }
  const std::string& label() const { return label_; }
  // Asks the worker to stop at its next progress report; it then finishes with ErrorCode::kCancelled.
  void cancel() {
    if (state_) state_->cancel.store(true, std::memory_order_relaxed);
  }
  bool cancelRequested() const { return state_ && state_->cancel.load(std::memory_order_relaxed); }

  // The result once the worker has finished, handed out once; nullopt while running or when idle. A job cancelled
  // gives kCancelled even when its work finished anyway (a cancel pressed after its last progress report): what the
  // user cancelled never lands (unless started with keeps_late_result: then the user is told what it did).
  std::optional<Result<T>> take() {
    joinRetired();
    if (!state_ || !state_->done.load(std::memory_order_acquire)) return std::nullopt;
    thread_.join();
    std::optional<Result<T>> out = std::move(state_->result);
    if (!keeps_late_result_ && state_->cancel.load(std::memory_order_relaxed) && out && out->ok()) {
      out.emplace(makeError(ErrorCode::kCancelled, label_ + ": cancelled"));
    }
    state_.reset();
    return out;
  }

  // Drops a running job's result: cancels it and lets it finish in the background.
  void abandon() { retire(); }

 private:
  struct State {
    std::atomic<double> progress{0.0};
    std::atomic<bool> cancel{false};
    std::atomic<bool> done{false};
    std::optional<Result<T>> result;  // written by the worker before `done` is released
  };
  struct Retired {
    std::shared_ptr<State> state;
    std::jthread thread;
  };

  void retire() {
    joinRetired();
    if (!state_) return;
    state_->cancel.store(true, std::memory_order_relaxed);
    retired_.push_back(Retired{std::move(state_), std::move(thread_)});
    state_.reset();
  }
  void joinRetired() {
    std::erase_if(retired_, [](Retired& r) { return r.state->done.load(std::memory_order_acquire); });
  }

  std::string label_;
  bool keeps_late_result_ = false;
  std::shared_ptr<State> state_;
  std::jthread thread_;
  std::vector<Retired> retired_;
};

// A value computed in the background for a key (e.g. the X-ray of model version 7 along Z in max mode). The window
// asks for the key it needs every frame; a new key starts a computation, the old one is abandoned.
template <class Key, class T>
class AsyncValue {
 public:
  // True when `key` has neither a value (or error) nor a computation under way: request() would start one.
  bool wants(const Key& key) const {
    return !((value_ || error_) && value_key_ == key) && !(job_.active() && job_key_ == key);
  }
  // Makes sure the value for `key` is present or being computed; `work` runs only when it is neither.
  void request(const Key& key, const std::string& label, typename Job<T>::Work work) {
    if (!wants(key)) return;
    job_key_ = key;
    job_.start(label, std::move(work));
  }
  // Moves a finished result in; returns true when something arrived.
  bool poll() {
    auto r = job_.take();
    if (!r) return false;
    value_key_ = job_key_;
    if (r->ok()) {
      value_ = std::move(*r).value();
      error_.reset();
    } else {
      value_.reset();
      error_ = r->error();
    }
    return true;
  }
  // The value for exactly this key, or null.
  const T* get(const Key& key) const { return value_ && value_key_ == key ? &*value_ : nullptr; }
  const Error* error(const Key& key) const { return error_ && value_key_ == key ? &*error_ : nullptr; }
  // The value held, whatever its key (null when none).
  const T* held() const { return value_ ? &*value_ : nullptr; }
  // The value held becomes the value for `key` (the caller knows it is: the same input under another key); a
  // computation under way for another key is abandoned.
  void rekey(const Key& key) {
    if (!value_) return;
    if (job_.active() && job_key_ != key) job_.abandon();
    value_key_ = key;
  }
  bool computing(const Key& key) const { return job_.active() && job_key_ == key; }
  bool busy() const { return job_.active(); }
  double progress() const { return job_.progress(); }
  void clear() {
    job_.abandon();
    value_.reset();
    error_.reset();
  }

 private:
  Job<T> job_;
  Key job_key_{};
  Key value_key_{};
  std::optional<T> value_;
  std::optional<Error> error_;
};

}  // namespace vox::app
