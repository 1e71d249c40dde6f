// Bodies of an assembly, each voxelized over its own box of the whole mesh's lattice (GridPlacement::first keeps the
// centres those of the whole grid, exactly), bodies in parallel with one thread each: most bodies are small, and a
// thread per body keeps every core busy without splitting small grids.
#include "vox/voxelize/bodies.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <numeric>
#include <thread>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "vox/core/parallel.h"
#include "vox/core/text.h"

namespace vox {

namespace {

// The params for body `i` alone: its box of the lattice, one thread.
VoxelizeParams bodyParams(const VoxelizeParams& params, const GridPlacement& whole, const Box3d& bounds) {
  VoxelizeParams p = params;
  glm::ivec3 begin, end;
  latticeRange(whole, bounds, begin, end);
  const glm::ivec3 size = glm::max(end - begin, glm::ivec3(1));
  p.placement = placeGridOnLattice(whole.frame, begin, Dims{size.x, size.y, size.z});
  p.threads = 1;
  return p;
}

}  // namespace

Result<BodiesResult> voxelizeBodies(const TriangleMesh& mesh, const VoxelizeParams& params, const ProgressFn& progress,
                                    const MeshBodies* given) {
  const std::string name = mesh.name.empty() ? std::string("the mesh") : mesh.name;
  if (mesh.triangles.empty()) return makeError(ErrorCode::kParse, name + " has no triangles");
  auto plan = planVoxelization(mesh.bounds(), params);
  if (!plan) return plan.error();
  BodiesResult out;
  out.placement = plan->placement;
  out.lattice = Lattice{out.placement.frame.origin + glm::dvec3(out.placement.first) * out.placement.frame.voxel_size,
                        out.placement.frame.voxel_size, params.units};
  MeshBodies split;
  if (!given) split = splitBodies(mesh);
  const MeshBodies& bodies = given ? *given : split;
  const size_t n = bodies.count();
  out.bodies.resize(n);

  // Largest bodies first, so the last ones handed out are short.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return bodies.triangles[a].size() > bodies.triangles[b].size(); });
  const int threads = params.threads > 0 ? params.threads : std::max(1, int(std::thread::hardware_concurrency()));
  std::vector<std::string> body_warnings(n);
  std::mutex mutex;
  std::optional<Error> failure;
  std::atomic<int64_t> done{0};
  std::atomic<bool> stop{false};
  parallelChunks(0, int64_t(n), 1, threads, [&](int, int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1 && !stop.load(); ++k) {
      const size_t i = order[size_t(k)];
      const TriangleMesh body = bodyMesh(mesh, bodies, i);
      const VoxelizeParams p = bodyParams(params, out.placement, body.bounds());
      auto r = voxelizeSolid(body, p);
      if (!r) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = makeError(r.error().code, "body " + std::to_string(i) + ": " + r.error().message);
        stop.store(true);
        return;
      }
      BodyVoxels& b = out.bodies[i];
      b.triangles = int64_t(body.triangles.size());
      b.mode_used = r->mode_used;
      b.voxels.first = p.placement->first;
      b.voxels.grid = std::move(r->grid);
      b.voxels.grid.frame().units = params.units;
      b.filled = b.voxels.grid.filledCount();
      for (const std::string& w : r->warnings) body_warnings[i] += "body " + std::to_string(i) + ": " + w + "\n";
      const int64_t d = done.fetch_add(1) + 1;
      if (progress) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!stop.load() && !progress(double(d) / double(n))) stop.store(true);
      }
    }
  });
  if (failure) return *failure;
  if (stop.load()) return makeError(ErrorCode::kCancelled, "voxelization cancelled");
  for (const std::string& w : body_warnings) {
    size_t at = 0;
    while (at < w.size()) {
      const size_t nl = w.find('\n', at);
      out.warnings.push_back(w.substr(at, nl - at));
      at = nl + 1;
    }
  }
  return out;
}

}  // namespace vox
