#pragma once
// Shared helpers for the benchmarks: where the shared meshes are, and the grid a benchmark works on.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"

namespace vox::bench {

inline std::filesystem::path sharedDir() {
  const char* env = std::getenv("VOXMOD_SHARED_DIR");
  return env && *env ? std::filesystem::path(env) : std::filesystem::path(VOXMOD_SHARED_DIR);
}
inline std::filesystem::path sharedMesh(const std::string& name) { return sharedDir() / "meshes" / name; }

inline std::string envOr(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

// The shared mesh VOXMOD_BENCH_MESH (default `mesh`) voxelized at VOXMOD_BENCH_R (default `resolution`), once per
// process; exits with the message when it cannot be made.
inline const VoxelGrid& benchGridFromEnv(const char* mesh, const char* resolution) {
  static std::unique_ptr<VoxelGrid> grid;
  if (grid) return *grid;
  const std::string name = envOr("VOXMOD_BENCH_MESH", mesh);
  const int64_t r = std::atoll(envOr("VOXMOD_BENCH_R", resolution).c_str());
  auto stl = io::loadStl(sharedMesh(name + ".stl"));
  if (!stl) {
    std::fprintf(stderr, "%s\n", stl.error().message.c_str());
    std::exit(1);
  }
  VoxelizeParams p;
  p.resolution = r;
  auto v = voxelizeSolid(stl->mesh, p, {}, &stl->topology);
  if (!v) {
    std::fprintf(stderr, "%s\n", v.error().message.c_str());
    std::exit(1);
  }
  grid = std::make_unique<VoxelGrid>(std::move(v->grid));
  std::fprintf(stderr, "grid: %s at R = %lld: %d x %d x %d, %lld filled voxels, %.1f MiB\n", name.c_str(),
               static_cast<long long>(r), grid->nx(), grid->ny(), grid->nz(),
               static_cast<long long>(grid->filledCount()), double(grid->memoryBytes()) / (1 << 20));
  return *grid;
}

}  // namespace vox::bench
