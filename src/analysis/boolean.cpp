// Boolean operations between two voxel models on the same lattice (thesis 7.2 names set operations among the
// natural extensions of a voxel modeller): union, intersection, difference and symmetric difference (xor) are one
// word operation per 64 voxels. Layers that one operand lacks are handled without touching words: a union or xor
// keeps the first operand's layer or shares the second's (copy on write), an intersection leaves it empty, a
// difference keeps the first operand's layer.
#include <cmath>
#include <cstdio>
#include <string>

#include "vox/core/parallel.h"
#include "vox/core/text.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

std::string vecText(const glm::dvec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
  return buf;
}

// Same lattice: same dims, voxel size, origin and units. The source file name may differ. Voxel size and origin
// are compared to a relative 1e-9 of the voxel size so that a grid written to a file and read back still matches.
Status checkSameLattice(const VoxelGrid& a, const VoxelGrid& b) {
  if (a.dims() != b.dims()) {
    return makeError(ErrorCode::kInvalidArgument,
                     "grids differ in dimensions: " + dimsText(a.dims()) + " vs " + dimsText(b.dims()));
  }
  const double h = a.voxelSize();
  const double tol = 1e-9 * std::abs(h);
  if (std::abs(h - b.voxelSize()) > tol) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "grids differ in voxel size: %.17g vs %.17g", h, b.voxelSize());
    return makeError(ErrorCode::kInvalidArgument, buf);
  }
  const glm::dvec3 d = glm::abs(a.frame().origin - b.frame().origin);
  if (d.x > tol || d.y > tol || d.z > tol) {
    return makeError(ErrorCode::kInvalidArgument,
                     "grids differ in origin: " + vecText(a.frame().origin) + " vs " + vecText(b.frame().origin));
  }
  if (a.frame().units != b.frame().units) {
    return makeError(ErrorCode::kInvalidArgument,
                     "grids differ in units: '" + a.frame().units + "' vs '" + b.frame().units + "'");
  }
  return Ok{};
}

}  // namespace

Result<VoxelGrid> booleanOp(const VoxelGrid& a, const VoxelGrid& b, BoolOp op) {
  if (a.empty() || b.empty()) return makeError(ErrorCode::kInvalidArgument, "boolean of an empty grid (no dimensions)");
  if (Status s = checkSameLattice(a, b); !s) return s.error();

  VoxelGrid out = op == BoolOp::kIntersection ? VoxelGrid(a.dims(), a.frame()) : a;  // shares a's layers
  const int64_t n = a.wordsPerLayer();
  const int threads = threadsFor(b.allocatedLayers() * n);
  parallelChunks(0, a.nz(), 4, threads, [&](int, int64_t z0, int64_t z1) {
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      const bool ha = a.layerAllocated(z), hb = b.layerAllocated(z);
      if (!hb) continue;  // union, xor and difference keep a's layer; intersection stays empty
      if (!ha) {
        // a's layer is empty: union and xor are b's layer, shared; intersection and difference stay empty.
        if (op == BoolOp::kUnion || op == BoolOp::kXor) out.shareLayerFrom(b, z);
        continue;
      }
      // Both layers hold voxels: a fresh layer written once (no copy of a's layer first), given back when empty.
      const uint64_t* wa = a.layerWords(z);
      const uint64_t* wb = b.layerWords(z);
      uint64_t* w = out.freshLayerWords(z);
      uint64_t any = 0;
      switch (op) {
        case BoolOp::kUnion:
          for (int64_t i = 0; i < n; ++i) any |= w[i] = wa[i] | wb[i];
          break;
        case BoolOp::kIntersection:
          for (int64_t i = 0; i < n; ++i) any |= w[i] = wa[i] & wb[i];
          break;
        case BoolOp::kDifference:
          for (int64_t i = 0; i < n; ++i) any |= w[i] = wa[i] & ~wb[i];
          break;
        case BoolOp::kXor:
          for (int64_t i = 0; i < n; ++i) any |= w[i] = wa[i] ^ wb[i];
          break;
      }
      if (any == 0) out.releaseLayer(z);
    }
  });
  return out;
}

}  // namespace vox
