// Distance and thickness benchmarks: the shared mesh igea_refined_508k voxelized at R = 512 by vox::voxelizeSolid
// (override with VOXMOD_BENCH_MESH=<name> and VOXMOD_BENCH_R=<R>, e.g. 1000).
//   distance/0      exact Euclidean distance transform (SPEC section 6) of the filled voxels, packed rows; first_ms:
//                   the first of the iterations alone, which pays for the process's fresh memory as a CLI run does
//   distance/1      the same computed dense, as local thickness and hot spots take it
//   dense_copy      a dense copy of the packed field (what computing it dense saves)
//   thickness       local thickness from the dense field (its copy made outside the timing)
//   hot_spots       regional maxima of the dense distance field with their dynamics
//   thin_walls      thin-wall regions below 10% of the largest thickness
//   rays            ray thickness (--method ray) from the mesh's own surface, painted over the grid (ray origins per
//                   voxel face of area: VOXMOD_BENCH_SAMPLES, default 2 as the CLI casts)
// Peak memory of one step alone: run with --benchmark_filter=<name> under /usr/bin/time -v.
//
//   build/bench/thickness_bench --benchmark_filter=distance
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/ray_thickness.h"
#include "vox/analysis/thickness.h"
#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"

namespace {

const vox::VoxelGrid& benchGrid() { return vox::bench::benchGridFromEnv("igea_refined_508k", "512"); }

// The distance field, dense (what hot spots and local thickness step through).
const vox::DistanceField& benchDistance() {
  static std::unique_ptr<vox::DistanceField> field;
  if (field) return *field;
  auto d = vox::computeDistance(benchGrid(), {}, vox::DistanceLayout::kDense);
  if (!d) {
    std::fprintf(stderr, "%s\n", d.error().message.c_str());
    std::exit(1);
  }
  field = std::make_unique<vox::DistanceField>(std::move(d.value()));
  return *field;
}

void distance(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  const auto layout = state.range(0) ? vox::DistanceLayout::kDense : vox::DistanceLayout::kPackedRows;
  bool first = true;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    auto d = vox::computeDistance(g, {}, layout);
    if (first) {
      state.counters["first_ms"] =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      first = false;
    }
    if (!d) state.SkipWithError(d.error().message.c_str());
    const vox::Dims b = d->boxDims();
    state.counters["box_voxels"] = double(b.count());
    state.counters["max_voxels"] = d->maxVoxels();
    state.counters["MiB"] = double(d->memoryBytes()) / (1 << 20);
  }
}

void denseCopy(benchmark::State& state) {
  auto d = vox::computeDistance(benchGrid());
  if (!d) {
    state.SkipWithError(d.error().message.c_str());
    return;
  }
  for (auto _ : state) {
    vox::DistanceField dense = d->denseCopy();
    if (!dense.data()) state.SkipWithError("no memory for the dense copy");
    benchmark::DoNotOptimize(dense.data());
  }
}

void thickness(benchmark::State& state) {
  const vox::DistanceField& d = benchDistance();
  for (auto _ : state) {
    state.PauseTiming();
    vox::DistanceField copy = d.denseCopy();
    state.ResumeTiming();
    auto t = vox::computeThickness(std::move(copy));
    if (!t) state.SkipWithError(t.error().message.c_str());
    state.counters["ball_centres"] = double(t->ball_centres);
    state.counters["mean_voxels"] = t->stats.mean / d.voxelSize();
    state.counters["max_voxels"] = t->stats.max / d.voxelSize();
  }
}

void hotSpots(benchmark::State& state) {
  const vox::DistanceField& d = benchDistance();
  for (auto _ : state) {
    auto s = vox::findHotSpots(d);
    if (!s) state.SkipWithError(s.error().message.c_str());
    state.counters["spots"] = double(s->size());
    int isolated = 0;
    for (const auto& h : *s) isolated += h.isolated;
    state.counters["isolated"] = isolated;
  }
}

void thinWalls(benchmark::State& state) {
  const vox::DistanceField& d = benchDistance();
  auto t = vox::computeThickness(d);
  if (!t) {
    state.SkipWithError(t.error().message.c_str());
    return;
  }
  for (auto _ : state) {
    auto w = vox::findThinWalls(*t, 0.1 * t->stats.max);
    if (!w) state.SkipWithError(w.error().message.c_str());
    state.counters["thin_voxels"] = double(w->voxels);
    state.counters["regions"] = double(w->regions.size());
  }
}

void rays(benchmark::State& state) {
  const vox::VoxelGrid& g = benchGrid();
  auto stl =
      vox::io::loadStl(vox::bench::sharedMesh(vox::bench::envOr("VOXMOD_BENCH_MESH", "igea_refined_508k") + ".stl"));
  if (!stl) {
    state.SkipWithError(stl.error().message.c_str());
    return;
  }
  vox::RayThicknessParams p;
  p.paint_limit = 2.0 * benchDistance().maxModel() + 2.0 * g.voxelSize();  // as the workflow passes it
  p.samples_per_face = std::atof(vox::bench::envOr("VOXMOD_BENCH_SAMPLES", "2").c_str());
  for (auto _ : state) {
    auto r = vox::computeRayThickness(stl->mesh, g, p);
    if (!r) {
      state.SkipWithError(r.error().message.c_str());
      break;
    }
    state.counters["rays"] = double(r->rays);
    state.counters["accepted"] = double(r->accepted);
    state.counters["voxels"] = double(r->voxels);
  }
}

}  // namespace

BENCHMARK(distance)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK(denseCopy)->Name("dense_copy")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(thickness)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()->Iterations(1);
BENCHMARK(hotSpots)
    ->Name("hot_spots")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(thinWalls)
    ->Name("thin_walls")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(rays)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()->Iterations(1);

BENCHMARK_MAIN();
