#include "vox/core/grid_placement.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

namespace vox {
namespace {

Result<GridPlacement> place(const Box3d& bounds, double h, int64_t resolution) {
  const glm::dvec3 e = bounds.extent();
  GridPlacement p;
  p.resolution = int32_t(resolution);
  p.frame.origin = bounds.min;
  p.frame.voxel_size = h;
  auto axis = [&](double extent) {
    // ceil(extent / h) may come out one too high through rounding on the longest axis; that axis has R voxels.
    const double n = std::ceil(extent / h);
    return int32_t(std::clamp<double>(n, 1.0, double(resolution)));
  };
  p.dims = Dims{axis(e.x), axis(e.y), axis(e.z)};
  return p;
}

Status checkBounds(const Box3d& bounds) {
  if (bounds.empty()) return makeError(ErrorCode::kParse, "the mesh has no vertices");
  const glm::dvec3 e = bounds.extent();
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(bounds.min[a]) || !std::isfinite(bounds.max[a]))
      return makeError(ErrorCode::kParse, "the bounding box is not finite");
  }
  if (std::max({e.x, e.y, e.z}) <= 0.0)
    return makeError(ErrorCode::kParse, "the mesh has zero extent (all vertices coincide)");
  return Ok{};
}

}  // namespace

Result<GridPlacement> placeGridByResolution(const Box3d& bounds, int64_t resolution) {
  if (resolution < 1 || resolution > kMaxResolution) {
    return makeError(ErrorCode::kInvalidArgument, "resolution " + std::to_string(resolution) +
                                                      " is out of range (1 to " + std::to_string(kMaxResolution) + ")");
  }
  if (auto s = checkBounds(bounds); !s) return s.error();
  const glm::dvec3 e = bounds.extent();
  const double extent = std::max({e.x, e.y, e.z});
  return place(bounds, extent / double(resolution), resolution);
}

Result<GridPlacement> placeGridByVoxelSize(const Box3d& bounds, double voxel_size) {
  if (!(voxel_size > 0.0) || !std::isfinite(voxel_size)) {
    return makeError(ErrorCode::kInvalidArgument, "voxel size must be a positive number");
  }
  if (auto s = checkBounds(bounds); !s) return s.error();
  const glm::dvec3 e = bounds.extent();
  const double extent = std::max({e.x, e.y, e.z});
  const double r = std::ceil(extent / voxel_size);
  if (r > double(kMaxResolution)) {
    return makeError(ErrorCode::kLimit, "voxel size " + std::to_string(voxel_size) + " gives " +
                                            std::to_string(int64_t(std::min(r, 1e15))) +
                                            " voxels on the longest axis (at most " + std::to_string(kMaxResolution) +
                                            ")");
  }
  return place(bounds, voxel_size, std::max<int64_t>(1, int64_t(r)));
}

}  // namespace vox

namespace vox {

GridPlacement placeGridOnLattice(const GridFrame& lattice, const glm::ivec3& first, const Dims& dims) {
  GridPlacement p;
  p.frame = lattice;
  p.dims = dims;
  p.first = first;
  p.resolution = std::max({dims.nx, dims.ny, dims.nz});
  return p;
}

void latticeRange(const GridPlacement& placement, const Box3d& bounds, glm::ivec3& begin, glm::ivec3& end) {
  const glm::ivec3 n(placement.dims.nx, placement.dims.ny, placement.dims.nz);
  const double h = placement.frame.voxel_size;
  for (int a = 0; a < 3; ++a) {
    // Centre I lies at origin + (I + 0.5) h. One voxel of margin on either side absorbs every rounding of this
    // estimate; the voxelizer decides each centre exactly, so extra voxels only stay empty.
    const double lo = std::floor((bounds.min[a] - placement.frame.origin[a]) / h - 0.5) - 1.0;
    const double hi = std::ceil((bounds.max[a] - placement.frame.origin[a]) / h - 0.5) + 2.0;
    const double first = placement.first[a], last = double(placement.first[a]) + n[a];
    begin[a] = int32_t(std::clamp(lo, first, last));
    end[a] = int32_t(std::clamp(hi, double(begin[a]), last));
  }
}

}  // namespace vox

namespace vox {

Result<GridPlacement> placeBoundsOnLattice(const GridFrame& lattice, const Box3d& bounds) {
  if (auto s = checkBounds(bounds); !s) return makeError(ErrorCode::kInvalidArgument, s.error().message);
  const double h = lattice.voxel_size;
  glm::ivec3 first(0);
  Dims dims;
  for (int a = 0; a < 3; ++a) {
    // As latticeRange: one voxel of margin past the centres nearest the box's faces.
    const double lo = std::floor((bounds.min[a] - lattice.origin[a]) / h - 0.5) - 1.0;
    const double hi = std::ceil((bounds.max[a] - lattice.origin[a]) / h - 0.5) + 2.0;
    if (!(std::abs(lo) < 1073741824.0 && std::abs(hi) < 1073741824.0)) {
      return makeError(ErrorCode::kLimit, "the mesh lies more than 2^30 voxels from the lattice's origin");
    }
    if (hi - lo > double(kMaxResolution)) {
      return makeError(ErrorCode::kLimit, "the mesh spans " + std::to_string(int64_t(hi - lo)) +
                                              " voxels of the lattice along an axis (at most " +
                                              std::to_string(kMaxResolution) + ")");
    }
    first[a] = int32_t(lo);
    (a == 0 ? dims.nx : a == 1 ? dims.ny : dims.nz) = std::max(1, int32_t(hi - lo));
  }
  return placeGridOnLattice(lattice, first, dims);
}

}  // namespace vox
