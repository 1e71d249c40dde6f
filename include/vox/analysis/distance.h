#pragma once
// Exact Euclidean distance transform (docs/conventions.md, "Distance and thickness") and the skin removal it
// defines.
//
// Distance of a filled voxel: the Euclidean distance from its centre to the nearest empty voxel centre, every centre
// outside the grid counting as empty (SciPy's ndimage.distance_transform_edt of the grid padded by one empty voxel).
// Clearance of an empty voxel: its distance to the nearest filled voxel centre (centres outside the grid are empty,
// so they never count). Both are kept squared, as exact integers (voxel units^2).
//
// Method: the separable exact transform of Felzenszwalb and Huttenlocher (2012, the lower envelope of parabolas),
// pass 1 along X straight from the grid's bit words (runs found with word operations, no byte copy of the grid),
// then Y and Z in place, parallel over lines with per-thread scratch. Every zero of a line (a voxel that is its own
// nearest site) splits the line into independent pieces, so each pass works only on the runs between zeros.
// Memory: a distance field stores one uint32 per voxel of each row's span of filled voxels (packed rows, below; or
// per voxel of its box, dense, when asked for), a clearance field one per voxel of the grid, from calloc, written only
// where a value is not zero, so pages that stay zero are never faulted in; nothing else the size of the grid. The
// blocks of 2 MiB that the passes write most of are advised onto 2 MiB pages first (Linux), up to a sixth more resident
// memory than 4 KiB pages alone (figures: docs/performance.md, "Distance and thickness").
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// Squared distances over a box of the grid (voxel coordinates box_min .. box_min + box_dims - 1, all inside the
// grid). Voxels of the grid outside the box have the value `outside` (0 for a distance field: they are all empty).
//
// Two layouts of the values. Dense: every voxel of the box, x fastest, then y, then z (what consumers that step
// through the box by constant strides need: local thickness, hot spots). Packed rows: each row of the box keeps only
// its span, from its first voxel with a value to its last, the rows one after another; the voxels of a row outside
// its span have the value `outside`. A distance field is computed packed unless asked for dense (about half the
// memory a dense field touches, whose rows' ends outside the part share pages with the part); denseCopy() makes a
// dense field from a packed one.
class DistanceField {
 public:
  static constexpr uint32_t kInfinite = UINT32_MAX;  // clearance in a grid without filled voxels

  // Where a row of the box lies: the values of box x in [lo, hi) at data()[base + x].
  struct Row {
    int64_t base = 0;
    int32_t lo = 0, hi = 0;
  };

  DistanceField() = default;
  // Dense, every value zero.
  DistanceField(Dims grid_dims, GridFrame frame, glm::ivec3 box_min, Dims box_dims, uint32_t outside);
  // Packed rows, every stored value zero: spans[y + ny z] gives row (y, z)'s span [lo, hi) in box x (lo == hi: none);
  // the bases are assigned here.
  DistanceField(Dims grid_dims, GridFrame frame, glm::ivec3 box_min, Dims box_dims, uint32_t outside,
                std::vector<Row> spans);
  DistanceField(DistanceField&&) = default;
  DistanceField& operator=(DistanceField&&) = default;

  const Dims& gridDims() const { return grid_dims_; }
  const GridFrame& frame() const { return frame_; }
  double voxelSize() const { return frame_.voxel_size; }
  // The box the values are stored for (empty box: no filled voxel, every value is `outside`).
  glm::ivec3 boxMin() const { return box_min_; }
  const Dims& boxDims() const { return box_dims_; }
  bool inBox(int64_t x, int64_t y, int64_t z) const {
    return x >= box_min_.x && y >= box_min_.y && z >= box_min_.z && x < box_min_.x + box_dims_.nx &&
           y < box_min_.y + box_dims_.ny && z < box_min_.z + box_dims_.nz;
  }
  bool isDense() const { return rows_.empty(); }
  // Row (y, z) of the box (box coordinates), either layout.
  Row row(int64_t y, int64_t z) const {
    const int64_t r = y + int64_t(box_dims_.ny) * z;
    return isDense() ? Row{r * box_dims_.nx, 0, box_dims_.nx} : rows_[size_t(r)];
  }
  // Index into data() of a voxel inside the box (grid coordinates), dense layout only.
  int64_t boxIndex(int64_t x, int64_t y, int64_t z) const {
    return (x - box_min_.x) + int64_t(box_dims_.nx) * ((y - box_min_.y) + int64_t(box_dims_.ny) * (z - box_min_.z));
  }

  // Squared distance (voxel units^2) of a voxel of the grid; `outside` for voxels outside the box or their row's span.
  uint32_t squared(int64_t x, int64_t y, int64_t z) const {
    if (!inBox(x, y, z)) return outside_;
    const int64_t xi = x - box_min_.x;
    const Row r = row(y - box_min_.y, z - box_min_.z);
    return xi >= r.lo && xi < r.hi ? data_.get()[r.base + xi] : outside_;
  }
  double voxels(int64_t x, int64_t y, int64_t z) const { return toVoxels(squared(x, y, z)); }
  double model(int64_t x, int64_t y, int64_t z) const { return voxels(x, y, z) * voxelSize(); }
  static double toVoxels(uint32_t squared) { return squared == kInfinite ? INFINITY : std::sqrt(double(squared)); }

  // Largest finite squared value; its distance in voxels and model units.
  uint32_t maxSquared() const { return max_squared_; }
  double maxVoxels() const { return toVoxels(max_squared_); }
  double maxModel() const { return maxVoxels() * voxelSize(); }

  // The stored values (storedValues() of them): dense, the box's, x fastest, then y, then z; packed, the rows' spans
  // (see row()).
  const uint32_t* data() const { return data_.get(); }
  uint32_t* data() { return data_.get(); }
  int64_t storedValues() const { return stored_; }
  uint32_t outside() const { return outside_; }
  // The values and the rows' table.
  size_t memoryBytes() const { return size_t(stored_) * sizeof(uint32_t) + rows_.size() * sizeof(Row); }

  void setMaxSquared(uint32_t m) { max_squared_ = m; }

  // A dense copy (of either layout); a field without values when its memory cannot be allocated (data() null while
  // the box is not empty).
  DistanceField denseCopy() const;

 private:
  struct Free {
    void operator()(uint32_t* p) const { std::free(p); }
  };
  Dims grid_dims_{};
  GridFrame frame_{};
  glm::ivec3 box_min_{0};
  Dims box_dims_{};
  uint32_t outside_ = 0;
  uint32_t max_squared_ = 0;
  int64_t stored_ = 0;
  std::vector<Row> rows_;                   // packed rows; empty when dense
  std::unique_ptr<uint32_t[], Free> data_;  // calloc: pages nothing writes (zeros) are never touched
};

enum class DistanceLayout { kPackedRows, kDense };

// Distance of every filled voxel to the empty space (0 in empty voxels). The box is the filled voxels' bounding box,
// stored as packed rows, or dense for consumers that step through the box by strides (local thickness, hot spots:
// computing it dense costs what packed rows cost, where a dense copy afterwards touches the whole box's memory
// again). Cost: O(box voxels), parallel; memory: 4 bytes per voxel of the rows' spans (packed) or of the rows that
// meet the part (dense).
Result<DistanceField> computeDistance(const VoxelGrid& grid, const ProgressFn& progress = {},
                                      DistanceLayout layout = DistanceLayout::kPackedRows);
// Clearance of every empty voxel to the material (0 in filled voxels, DistanceField::kInfinite everywhere when the
// grid has no filled voxel). The box is the whole grid, dense.
Result<DistanceField> computeClearance(const VoxelGrid& grid, const ProgressFn& progress = {});

// Round skin removal: the grid without every filled voxel whose distance is at most
// `distance_model` (model units). The input is not modified; untouched layers stay shared with it.
Result<VoxelGrid> peelByDistance(const VoxelGrid& grid, double distance_model, const ProgressFn& progress = {});
// The same from a distance field already computed for `grid`.
VoxelGrid peelByDistance(const VoxelGrid& grid, const DistanceField& distance, double distance_model);

}  // namespace vox
