// CAD input benchmarks: a STEP assembly (../shared/meshes/cad/as1-oc-214.stp, 18 placed solids) read and healed,
// tessellated for a grid of resolution R (deflection 0.04 voxel, docs/accuracy.md) and voxelized at R, each step on
// its own and the whole path as `voxmod voxelize` takes it (loadMeshFile, then voxelizeSolid). Wall time: the mesher
// and the voxelizer use both cores. VOXMOD_BENCH_CAD names another file of that folder, VOXMOD_BENCH_R another R.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "bench_support.h"
#include "vox/io/cad.h"
#include "vox/io/mesh_file.h"
#include "vox/voxelize/voxelize.h"

namespace {

std::filesystem::path cadFile() {
  return vox::bench::sharedDir() / "meshes" / "cad" / vox::bench::envOr("VOXMOD_BENCH_CAD", "as1-oc-214.stp");
}
int64_t resolution() { return std::atoll(vox::bench::envOr("VOXMOD_BENCH_R", "500").c_str()); }

const vox::io::CadModel* model(benchmark::State& state) {
  static auto m = vox::io::readCadFile(cadFile());
  if (!m) state.SkipWithError(m.error().message.c_str());
  return m ? &*m : nullptr;
}

void BM_CadRead(benchmark::State& state) {
  for (auto _ : state) {
    auto m = vox::io::readCadFile(cadFile());
    if (!m) {
      state.SkipWithError(m.error().message.c_str());
      return;
    }
    state.counters["solids"] = double(m->solids());
  }
}
BENCHMARK(BM_CadRead)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CadTessellate(benchmark::State& state) {
  const vox::io::CadModel* m = model(state);
  if (!m) return;
  const double deflection = *vox::io::cadDeflectionFor(m->bounds(), resolution(), 0.0);
  for (auto _ : state) {
    auto t = vox::io::tessellateCad(*m, deflection);
    if (!t) {
      state.SkipWithError(t.error().message.c_str());
      return;
    }
    state.counters["triangles"] = double(t->mesh.triangles.size());
    state.counters["bodies"] = double(t->bodies.size());
  }
  state.counters["deflection_mm"] = deflection;
}
BENCHMARK(BM_CadTessellate)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CadVoxelize(benchmark::State& state) {
  const vox::io::CadModel* m = model(state);
  if (!m) return;
  auto t = vox::io::tessellateCad(*m, *vox::io::cadDeflectionFor(m->bounds(), resolution(), 0.0));
  vox::VoxelizeParams p;
  p.resolution = resolution();
  for (auto _ : state) {
    auto v = vox::voxelizeSolid(t->mesh, p, {}, &t->topology);
    if (!v) {
      state.SkipWithError(v.error().message.c_str());
      return;
    }
    state.counters["filled"] = double(v->grid.filledCount());
  }
}
BENCHMARK(BM_CadVoxelize)->Unit(benchmark::kMillisecond)->UseRealTime();

// Open, tessellate and voxelize, as the CLI does.
void BM_CadOpenTessellateVoxelize(benchmark::State& state) {
  vox::io::MeshFileOptions o;
  o.resolution = resolution();
  vox::VoxelizeParams p;
  p.resolution = resolution();
  for (auto _ : state) {
    auto m = vox::io::loadMeshFile(cadFile(), o);
    if (!m) {
      state.SkipWithError(m.error().message.c_str());
      return;
    }
    auto v = vox::voxelizeSolid(m->mesh, p, {}, &m->topology);
    if (!v) {
      state.SkipWithError(v.error().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(v->grid.filledCount());
  }
}
BENCHMARK(BM_CadOpenTessellateVoxelize)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
