// Analysis benchmarks (docs/performance.md) on a 1000^3 grid: the shared mesh fandisk voxelized at R = 1000 by
// vox::voxelizeSolid (override with VOXMOD_BENCH_MESH=<name>, e.g. armadillo, and VOXMOD_BENCH_R=<R>).
//   surface_stats            surface voxels + code histogram (thesis Table 5.1)
//   section_count/<axis>     filled count of one section, stepping through the indices like a slider
//   section_image/<axis>     the same with the mask image (what the GUI shows)
//   peel_one_layer           one skin layer
//   depth_map                the same, keeping the depth bit planes; then depth_map_remaining_after (one layer
//                            shown from the depth map)
//   xray/<axis>/<mode>       X-ray along each axis in each mode
//   mass                     mass properties
//
//   build-rel/bench/analysis_bench --benchmark_filter='section'
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "vox/analysis/analysis.h"
#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"

namespace {

const vox::VoxelGrid& benchGrid() { return vox::bench::benchGridFromEnv("fandisk", "1000"); }

int32_t axisLength(const vox::VoxelGrid& g, vox::Axis a) {
  return a == vox::Axis::kX ? g.nx() : (a == vox::Axis::kY ? g.ny() : g.nz());
}

void surfaceStats(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  for (auto _ : state) {
    const vox::SurfaceStats s = vox::computeSurfaceStats(g);
    benchmark::DoNotOptimize(s.surface_voxels);
    state.counters["surface_voxels"] = double(s.surface_voxels);
  }
}

// Steps through the indices of an axis by a stride that visits the whole range, like dragging a slider.
void sectionCount(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  const vox::Axis axis = vox::Axis(state.range(0));
  const int32_t n = axisLength(g, axis);
  int32_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(vox::sectionCount(g, axis, i));
    i = (i + 7) % n;
  }
  state.SetLabel(vox::axisName(axis));
}

void sectionImage(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  const vox::Axis axis = vox::Axis(state.range(0));
  const int32_t n = axisLength(g, axis);
  int32_t i = 0;
  for (auto _ : state) {
    auto s = vox::computeSection(g, vox::SectionParams{axis, i});
    benchmark::DoNotOptimize(s->filled);
    i = (i + 7) % n;
  }
  state.SetLabel(vox::axisName(axis));
}

void peelOneLayer(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  for (auto _ : state) {
    int64_t removed = 0;
    vox::VoxelGrid r = vox::peelOneLayer(g, &removed);
    benchmark::DoNotOptimize(removed);
    state.counters["removed"] = double(removed);
  }
}

void depthMap(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  for (auto _ : state) {
    auto d = vox::computeDepthMap(g);
    state.counters["layers"] = double(d->layers());
    state.counters["depth_MiB"] = double(d->memoryBytes()) / (1 << 20);
  }
}

void depthMapRemainingAfter(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  static auto d = vox::computeDepthMap(g);
  int32_t k = 1;
  for (auto _ : state) {
    vox::VoxelGrid r = d->remainingAfter(k);
    benchmark::DoNotOptimize(r.nz());
    k = k % d->layers() + 1;
  }
}

void xray(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  const vox::XrayParams p{vox::Axis(state.range(0)), vox::XrayMode(state.range(1))};
  for (auto _ : state) {
    auto r = vox::computeXray(g, p);
    benchmark::DoNotOptimize(r->mean);
  }
  state.SetLabel(std::string(vox::axisName(p.axis)) + "/" + vox::xrayModeName(p.mode));
}

void mass(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  for (auto _ : state) {
    const vox::MassProperties m = vox::computeMassProperties(g);
    benchmark::DoNotOptimize(m.volume);
  }
}

BENCHMARK(surfaceStats)->Name("surface_stats")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(sectionCount)
    ->Name("section_count")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(sectionImage)
    ->Name("section_image")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(peelOneLayer)->Name("peel_one_layer")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
BENCHMARK(depthMap)
    ->Name("depth_map")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(depthMapRemainingAfter)
    ->Name("depth_map_remaining_after")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(xray)
    ->Name("xray")
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(mass)->Name("mass")->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
