// Moving a part in the window (docs/performance.md, "Moving a part"): the cycloidal drive voxelized at R = 1000
// (VOXMOD_BENCH_R to change it) and split into its 100 bodies, as the Parts panel does, then one part moved by one
// voxel and back, again and again. Each move times what the window does on its main thread before it can draw the
// next frame: placePart (the new model state: the union of the parts) and syncRenderers (the renderers brought up to
// date: the part renderers and the model's). Needs an EGL context (llvmpipe is enough).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/actions.h"
#include "app/app_state.h"
#include "app/parts.h"
#include "app/update.h"
#include "app/viewport.h"
#include "bench_support.h"
#include "vox/render/context.h"

namespace vox::app {
namespace {

void fail(const std::string& message) {
  std::fprintf(stderr, "parts_move_bench: %s\n", message.c_str());
  std::exit(1);
}

void run(AppState& state, const std::string& name, std::vector<std::string> words) {
  const Action* a = findAction(name);
  if (!a) fail("no action " + name);
  std::string rest;
  for (const std::string& w : words) rest += (rest.empty() ? "" : " ") + w;
  if (Status s = dispatch(state, *a, ActionArgs{std::move(words), rest}); !s) fail(name + ": " + s.error().message);
}

template <class F>
void pump(AppState& state, F done) {
  while (!done()) {
    updateDocument(state);
    if (!state.errors.messages.empty()) fail(state.errors.messages.back());
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

struct Scene {
  std::unique_ptr<render::HeadlessContext> context;
  AppState state;
};

Scene& scene() {
  static std::unique_ptr<Scene> s;
  if (s) return *s;
  s = std::make_unique<Scene>();
  auto ctx = render::HeadlessContext::create();
  if (!ctx) fail(ctx.error().message);
  s->context = std::move(ctx).value();
  AppState& state = s->state;
  if (Status v = initViewport(state); !v) fail(v.error().message);
  state.voxelize_dialog_on_open = false;
  run(state, "open", {bench::sharedMesh("cycloidal_assembly.stl").string()});
  pump(state, [&] { return state.doc.mesh != nullptr; });
  run(state, "voxelize", {bench::envOr("VOXMOD_BENCH_R", "1000")});
  pump(state, [&] { return state.doc.model.has_value(); });
  run(state, "split-bodies", {});
  pump(state, [&] { return currentParts(state) != nullptr; });
  run(state, "select-part", {"1"});
  syncRenderers(state);
  return *s;
}

// One move (alternately one voxel along X and back) of part N: 1 is the largest body (its box is most of the drive's),
// 100 the smallest.
void moveOnePart(benchmark::State& bench) {
  const std::string part = std::to_string(bench.range(0));
  Scene& s = scene();
  AppState& state = s.state;
  const double h = currentParts(state)->lattice().voxel_size;
  double place_s = 0.0, sync_s = 0.0;
  bool out = false;
  for (auto _ : bench) {
    out = !out;
    const auto t0 = std::chrono::steady_clock::now();
    run(state, "place-part", {part, std::to_string(out ? h : 0.0), "0", "0"});
    const auto t1 = std::chrono::steady_clock::now();
    syncRenderers(state);
    const auto t2 = std::chrono::steady_clock::now();
    place_s += std::chrono::duration<double>(t1 - t0).count();
    sync_s += std::chrono::duration<double>(t2 - t1).count();
  }
  const double n = double(bench.iterations());
  bench.counters["placePart_ms"] = 1e3 * place_s / n;
  bench.counters["syncRenderers_ms"] = 1e3 * sync_s / n;
  bench.counters["parts"] = double(currentParts(state)->size());
  bench.counters["model_voxels"] = double(state.model.filledCount());
}
BENCHMARK(moveOnePart)->Arg(1)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(4)->UseRealTime();

}  // namespace
}  // namespace vox::app

BENCHMARK_MAIN();
