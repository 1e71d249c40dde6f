// Point renderer benchmarks (docs/performance.md; thesis 6.2: "less than 2 seconds to generate an image of
// resolution up to 200", "of the order of 2 minutes for cube with resolution of 1000"). Shapes: a sphere of
// diameter R in an R^3 grid and a cube filling the R^3 grid, both built directly, and the shared armadillo
// voxelized at R (voxelizeSolid, auto mode; the voxelization itself is not timed). For R = 200, 400, 1000:
//   extract/<shape>/<R>   PointCloud::build: surface extraction (word operations) + packing into per-layer,
//                         per-code slices, all hardware threads;
//   gpu/<shape>/<R>       PointRenderer::setGrid + prepare: the above, then draw-order assembly and upload;
//   frame/<shape>/<R>     one full-detail frame at 1280x720 (fitted view, yaw 30, pitch 20, perspective, classic
//                         table, back-facing groups culled), glFinish included;
//   frame_nocull/...      the same without group culling;
//   frame_lod/...         the camera-motion frame: level of detail with the default budget (1M points);
//   image/<shape>/<R>     everything the thesis timed: points from the grid, upload, one 1280x720 frame, read-back.
// Counters: points (surface voxels of the set drawn), drawn (after culling), Mpts_per_s (drawn points per second
// of wall time). The CPU column is the whole process (llvmpipe threads included): on a loaded machine it is the
// steadier figure, since wall time there includes waiting for a core.
// Runs on the headless EGL context (llvmpipe on a machine without a GPU; LP_NUM_THREADS sets its threads).
//
//   build-rel/bench/render_bench --benchmark_filter='frame/sphere'
//
// With --voxmod_images=DIR it instead renders the documentation images (docs/images/render_*.png): spheres of
// diameter R = 100, 200, 400, 1000 at 800 x 800 (classic table, yaw 30, pitch 20: the thesis's Figure 6.2.3 set),
// and the armadillo at R = 400, lit, and cut away along Y.
//   build-rel/bench/render_bench --voxmod_images=docs/images
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "vox/io/image_io.h"
#include "vox/io/stl.h"
#include "vox/render/context.h"
#include "vox/render/framebuffer.h"
#include "vox/render/gl.h"
#include "vox/render/point_renderer.h"
#include "vox/render/render.h"
#include "vox/voxelize/voxelize.h"

namespace {

using vox::VoxelGrid;
namespace render = vox::render;

constexpr int32_t kWidth = 1280, kHeight = 720;

[[noreturn]] void die(const std::string& what) {
  std::fprintf(stderr, "render_bench: %s\n", what.c_str());
  std::exit(1);
}

render::HeadlessContext& context() {
  static std::unique_ptr<render::HeadlessContext> ctx = [] {
    auto c = render::HeadlessContext::create();
    if (!c) die(c.error().message);
    std::fprintf(stderr, "render_bench: %s on %s (%s)\n", c.value()->info().renderer.c_str(),
                 c.value()->info().platform.c_str(), c.value()->info().version.c_str());
    return std::move(c).value();
  }();
  return *ctx;
}

VoxelGrid sphere(int32_t r) {
  VoxelGrid g(vox::Dims{r, r, r});
  const double c = r * 0.5, radius = r * 0.5;
  for (int32_t z = 0; z < r; ++z) {
    for (int32_t y = 0; y < r; ++y) {
      const double dy = y + 0.5 - c, dz = z + 0.5 - c, h2 = radius * radius - dy * dy - dz * dz;
      if (h2 < 0) continue;
      const double h = std::sqrt(h2);
      g.fillRun(y, z, int64_t(std::ceil(c - h - 0.5)), int64_t(std::floor(c + h - 0.5)) + 1);
    }
  }
  return g;
}

const VoxelGrid& grid(const std::string& shape, int32_t r) {
  static std::map<std::pair<std::string, int32_t>, VoxelGrid> cache;
  auto key = std::make_pair(shape, r);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  VoxelGrid g;
  if (shape == "sphere") {
    g = sphere(r);
  } else if (shape == "cube") {  // the thesis's 2-minute case: every voxel of the R^3 grid filled
    g = VoxelGrid(vox::Dims{r, r, r});
    for (int32_t z = 0; z < r; ++z)
      for (int32_t y = 0; y < r; ++y) g.fillRun(y, z, 0, r);
  } else {
    auto stl = vox::io::loadStl(vox::bench::sharedMesh(shape + ".stl"));
    if (!stl) die(stl.error().message);
    vox::VoxelizeParams params;
    params.resolution = r;
    auto v = vox::voxelizeSolid(stl->mesh, params, {}, &stl->topology);
    if (!v) die(v.error().message);
    g = std::move(v->grid);
  }
  return cache.emplace(key, std::move(g)).first->second;
}

render::Camera viewOf(const render::PointRenderer& r) {
  render::RenderParams p;
  p.width = kWidth;
  p.height = kHeight;
  return render::cameraFor(r.bounds(), p);
}

void extract(benchmark::State& state, const std::string& shape, int32_t r) {
  const VoxelGrid& g = grid(shape, r);
  int64_t points = 0;
  for (auto _ : state) {
    render::PointCloud cloud(g);
    points = cloud.size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = double(points);
}

void gpu(benchmark::State& state, const std::string& shape, int32_t r) {
  const VoxelGrid& g = grid(shape, r);
  context();
  auto renderer = render::PointRenderer::create();
  if (!renderer) die(renderer.error().message);
  for (auto _ : state) {
    (*renderer)->setGrid(g);
    (*renderer)->prepare();
    glFinish();
  }
  state.counters["points"] = double((*renderer)->cloud().size());
}

// A renderer holding grid(shape, r), kept across the frame benchmarks of one grid.
render::PointRenderer& loaded(const std::string& shape, int32_t r) {
  static std::unique_ptr<render::PointRenderer> renderer;
  static std::pair<std::string, int32_t> holds;
  context();
  if (!renderer) {
    auto created = render::PointRenderer::create();
    if (!created) die(created.error().message);
    renderer = std::move(created).value();
  }
  if (holds != std::make_pair(shape, r)) {
    renderer->setGrid(grid(shape, r));
    renderer->prepare();
    holds = {shape, r};
  }
  return *renderer;
}

render::Framebuffer& framebuffer() {
  static render::Framebuffer fb = [] {
    render::Framebuffer f;
    if (auto s = f.resize(kWidth, kHeight); !s) die(s.error().message);
    return f;
  }();
  return fb;
}

void frame(benchmark::State& state, const std::string& shape, int32_t r, bool cull, bool lod) {
  render::PointRenderer& renderer = loaded(shape, r);
  render::Framebuffer& fb = framebuffer();
  const render::Camera cam = viewOf(renderer);
  render::DrawParams d;
  d.cull_back_groups = cull;
  d.coarse = lod;
  render::DrawStats stats;
  fb.clear({0, 0, 0, 255});
  renderer.draw(cam, kWidth, kHeight, d);  // warm-up: builds level-of-detail sets and compiles the shader variant
  glFinish();
  for (auto _ : state) {
    fb.clear({0, 0, 0, 255});
    stats = renderer.draw(cam, kWidth, kHeight, d);
    glFinish();
  }
  state.counters["points"] = double(stats.points_available);
  state.counters["drawn"] = double(stats.points_drawn);
  state.counters["lod"] = double(stats.lod_level);
  state.counters["point_px"] = stats.point_size_px;
  state.counters["Mpts_per_s"] =
      benchmark::Counter(double(stats.points_drawn) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

void image(benchmark::State& state, const std::string& shape, int32_t r) {
  const VoxelGrid& g = grid(shape, r);
  context();
  render::RenderParams p;
  p.width = kWidth;
  p.height = kHeight;
  for (auto _ : state) {
    auto img = render::renderGridInCurrentContext(g, p);
    if (!img) die(img.error().message);
    benchmark::DoNotOptimize(img->pixels.data());
  }
}

void registerAll() {
  for (const std::string shape : {"sphere", "cube", "armadillo"}) {
    for (int32_t r : {200, 400, 1000}) {
      const std::string tag = shape + "/" + std::to_string(r);
      const int iterations = r <= 200 ? 10 : r <= 400 ? 5 : 3;
      auto setup = [&](benchmark::internal::Benchmark* b) {
        // Process CPU time: llvmpipe rasterises on its own threads, so the calling thread alone says little.
        b->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(iterations);
      };
      setup(benchmark::RegisterBenchmark(("extract/" + tag).c_str(), extract, shape, r));
      setup(benchmark::RegisterBenchmark(("gpu/" + tag).c_str(), gpu, shape, r));
      setup(benchmark::RegisterBenchmark(("frame/" + tag).c_str(), frame, shape, r, true, false));
      setup(benchmark::RegisterBenchmark(("frame_nocull/" + tag).c_str(), frame, shape, r, false, false));
      setup(benchmark::RegisterBenchmark(("frame_lod/" + tag).c_str(), frame, shape, r, true, true));
      setup(benchmark::RegisterBenchmark(("image/" + tag).c_str(), image, shape, r));
    }
  }
}

void saveImage(const VoxelGrid& g, const render::RenderParams& p, const std::filesystem::path& path) {
  const auto t0 = std::chrono::steady_clock::now();
  auto img = render::renderGridInCurrentContext(g, p);
  if (!img) die(img.error().message);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (auto st = vox::io::savePng(*img, path); !st) die(st.error().message);
  std::printf("%s: %dx%d grid, %.2f s to render\n", path.string().c_str(), g.nx(), g.ny(), s);
}

int writeImages(const std::filesystem::path& dir) {
  context();
  render::RenderParams p;
  p.width = p.height = 800;
  for (int32_t r : {100, 200, 400, 1000}) {
    saveImage(sphere(r), p, dir / ("render_sphere_r" + std::to_string(r) + ".png"));
  }
  const VoxelGrid& armadillo = grid("armadillo", 400);
  render::RenderParams lit = p;
  lit.lut = render::Lut::kLit;
  lit.yaw_deg = 20;  // the armadillo stands along +Y and faces +Z
  lit.pitch_deg = 10;
  saveImage(armadillo, lit, dir / "render_armadillo_r400_lit.png");
  render::RenderParams cut = lit;
  cut.lut = render::Lut::kClassic;
  // A horizontal cut through the chest, looked at from above: the legs and hips below it, the cut face on top.
  cut.section = {render::SectionAxis::kY, armadillo.ny() * 3 / 5, render::SectionSide::kBelow};
  cut.yaw_deg = 25;
  cut.pitch_deg = 40;
  saveImage(armadillo, cut, dir / "render_armadillo_r400_cut_y.png");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--voxmod_images=", 0) == 0) return writeImages(a.substr(16));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
