#pragma once
// What the window's logic tests share: the per-frame update pumped until a job is done, an action given as a script
// line, and a headless GL context for the tests of the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/actions.h"
#include "app/app_state.h"
#include "app/operations.h"
#include "support/test_support.h"
#include "vox/render/context.h"

namespace vox::app::test_app {

// Pumps the per-frame update until `done` holds (the workers run in the background). A deadline, not a count of
// frames: under the thread sanitizer a job takes many times longer.
template <class F>
bool pump(AppState& state, F done, std::chrono::seconds limit = std::chrono::seconds(120)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    updateDocument(state);
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

// An action of the table given as a script gives it: its name, then its values.
inline Status run(AppState& state, const std::string& line) {
  std::vector<std::string> words;
  std::string rest;
  size_t start = 0;
  while (start < line.size()) {
    const size_t end = std::min(line.find(' ', start), line.size());
    words.push_back(line.substr(start, end - start));
    start = end + 1;
  }
  if (words.empty()) return makeError(ErrorCode::kInvalidArgument, "an empty line is no action");
  const Action* a = findAction(words[0]);
  if (!a) return makeError(ErrorCode::kInvalidArgument, "no action " + words[0]);
  words.erase(words.begin());
  if (const size_t sp = line.find(' '); sp != std::string::npos) rest = line.substr(sp + 1);
  return dispatch(state, *a, ActionArgs{words, rest});
}

// A headless GL context on Mesa's software rasteriser, for the tests of the view (an error where there is none).
inline Result<std::unique_ptr<render::HeadlessContext>> llvmpipeContext() {
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  return render::HeadlessContext::create();
}

}  // namespace vox::app::test_app

// Skips the test without a headless GL context (fails in CI, where Mesa's EGL is installed).
#define VOX_SKIP_WITHOUT_GL(context)                                                       \
  if (!(context)) {                                                                        \
    if (test::inCI()) FAIL() << "no headless OpenGL in CI: " << (context).error().message; \
    GTEST_SKIP() << "no headless OpenGL: " << (context).error().message;                   \
  }
