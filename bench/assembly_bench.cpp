// Assemblies (docs/performance.md, "Assemblies"): a Boolean of two 1000^3 parts, on equal boxes and on boxes
// shifted against each other (rows read across word boundaries); the cycloidal drive's 100 bodies split, voxelized
// on the assembly's lattice and all their interference at R = 1000 (VOXMOD_BENCH_R to change it).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "bench_support.h"
#include "vox/analysis/assembly.h"
#include "vox/core/mesh_bodies.h"
#include "vox/voxelize/bodies.h"

namespace vox {
namespace {

// A ball of radius r voxels centred in an n^3 grid, filled a row at a time.
VoxelGrid ball(int32_t n, double r) {
  VoxelGrid g(Dims{n, n, n});
  const double c = n / 2.0;
  for (int32_t z = 0; z < n; ++z)
    for (int32_t y = 0; y < n; ++y) {
      const double dy = y + 0.5 - c, dz = z + 0.5 - c, s = r * r - dy * dy - dz * dz;
      if (s <= 0) continue;
      const double half = std::sqrt(s);
      g.fillRun(y, z, int64_t(std::ceil(c - half - 0.5)), int64_t(std::floor(c + half - 0.5)) + 1);
    }
  return g;
}

const std::vector<LatticeGrid>& balls() {
  static std::unique_ptr<std::vector<LatticeGrid>> parts;
  if (!parts) {
    parts = std::make_unique<std::vector<LatticeGrid>>();
    parts->push_back(LatticeGrid{ball(1000, 490.0), glm::ivec3(0)});
    parts->push_back(LatticeGrid{ball(1000, 470.0), glm::ivec3(0)});
    parts->push_back(LatticeGrid{(*parts)[1].grid, glm::ivec3(137, 61, 29)});  // shifted: not word-aligned
  }
  return *parts;
}

void booleanEqualBoxes(benchmark::State& state) {
  const auto& p = balls();
  const PartOp op = PartOp(state.range(0));
  for (auto _ : state) {
    LatticeGrid r = booleanParts(p[0], p[1], op, Lattice{});
    benchmark::DoNotOptimize(r.grid.allocatedLayers());
  }
  state.SetLabel(partOpName(op));
}

void booleanShiftedBoxes(benchmark::State& state) {
  const auto& p = balls();
  const PartOp op = PartOp(state.range(0));
  for (auto _ : state) {
    LatticeGrid r = booleanParts(p[0], p[2], op, Lattice{});
    benchmark::DoNotOptimize(r.grid.allocatedLayers());
  }
  state.SetLabel(partOpName(op));
}

const TriangleMesh& cycloidal() {
  static std::unique_ptr<TriangleMesh> mesh;
  if (!mesh) {
    auto stl = io::loadStl(bench::sharedMesh("cycloidal_assembly.stl"));
    if (!stl) {
      std::fprintf(stderr, "%s\n", stl.error().message.c_str());
      std::exit(1);
    }
    mesh = std::make_unique<TriangleMesh>(std::move(stl->mesh));
  }
  return *mesh;
}

int64_t benchResolution() { return std::atoll(bench::envOr("VOXMOD_BENCH_R", "1000").c_str()); }

// Split, voxelize every body, and all interference: what `voxmod interfere --bodies` does after loading.
void bodiesAndInterference(benchmark::State& state) {
  const TriangleMesh& mesh = cycloidal();
  VoxelizeParams p;
  p.resolution = benchResolution();
  size_t pairs = 0;
  for (auto _ : state) {
    const MeshBodies bodies = splitBodies(mesh);
    auto r = voxelizeBodies(mesh, p, {}, &bodies);
    std::vector<LatticeGrid> parts;
    for (BodyVoxels& b : r->bodies) parts.push_back(std::move(b.voxels));
    const Interference i = findInterference(parts, r->lattice);
    pairs = i.pairs.size();
  }
  state.counters["pairs"] = double(pairs);
}

// The steps alone.
void splitOnly(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(splitBodies(cycloidal()).count());
}

void voxelizeBodiesOnly(benchmark::State& state) {
  VoxelizeParams p;
  p.resolution = benchResolution();
  const MeshBodies bodies = splitBodies(cycloidal());
  for (auto _ : state) benchmark::DoNotOptimize(voxelizeBodies(cycloidal(), p, {}, &bodies)->bodies.size());
}

void wholeMeshVoxelize(benchmark::State& state) {
  VoxelizeParams p;
  p.resolution = benchResolution();
  p.mode = FillMode::kNonzero;
  for (auto _ : state) benchmark::DoNotOptimize(voxelizeSolid(cycloidal(), p)->grid.nz());
}

void interferenceOnly(benchmark::State& state) {
  VoxelizeParams p;
  p.resolution = benchResolution();
  auto r = voxelizeBodies(cycloidal(), p);
  std::vector<LatticeGrid> parts;
  for (BodyVoxels& b : r->bodies) parts.push_back(std::move(b.voxels));
  for (auto _ : state) benchmark::DoNotOptimize(findInterference(parts, r->lattice).pairs.size());
}

#define VOX_BENCH(fn, name) \
  BENCHMARK(fn)->Name(name)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()

VOX_BENCH(booleanEqualBoxes, "boolean_1000_equal_boxes")->DenseRange(0, 3);
VOX_BENCH(booleanShiftedBoxes, "boolean_1000_shifted_boxes")->DenseRange(0, 3);
VOX_BENCH(bodiesAndInterference, "cycloidal_split_voxelize_interfere");
VOX_BENCH(splitOnly, "cycloidal_split");
VOX_BENCH(voxelizeBodiesOnly, "cycloidal_voxelize_bodies");
VOX_BENCH(wholeMeshVoxelize, "cycloidal_voxelize_whole_mesh");
VOX_BENCH(interferenceOnly, "cycloidal_interference");

}  // namespace
}  // namespace vox

BENCHMARK_MAIN();
