#pragma once
// Geometric analysis of a voxel model (thesis chapter 5.2): surface statistics, sections, skin removal, X-ray
// thickness, mass properties, booleans. No GL; the CLI and the GUI call these with the same params structs.
// Images follow vox/core/image.h (row 0 at the top). Counts are in voxels; *_mm values in model units.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "vox/core/image.h"
#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

enum class Axis { kX = 0, kY = 1, kZ = 2 };
const char* axisName(Axis a);  // "x", "y", "z"
std::optional<Axis> parseAxis(const std::string& s);
// The grid axes a section or X-ray image normal to `normal` shows along its columns (right) and rows (up):
// X -> (y, z), Y -> (x, z), Z -> (x, y); row 0 holds the largest index along the up axis.
Axis imageRightAxis(Axis normal);
Axis imageUpAxis(Axis normal);

// ---- Surface and codes (thesis Table 5.1) ----
struct SurfaceStats {
  int64_t filled = 0;
  int64_t surface_voxels = 0;                // filled with at least one empty face neighbour
  std::array<int64_t, 64> code_histogram{};  // over all filled voxels; [63] = interior
  int64_t suspect_voxels = 0;                // four or five free faces: likely voxelization errors (thesis 4.3.3)
};
SurfaceStats computeSurfaceStats(const VoxelGrid& grid);

// ---- Section (thesis 5.2.1) ----
struct SectionParams {
  Axis axis = Axis::kZ;
  int32_t index = 0;  // voxel index along the axis, 0 <= index < n_axis
};
struct Section {
  Axis axis = Axis::kZ;
  int32_t index = 0;
  double position = 0.0;  // model-unit coordinate of the cut plane (the voxel centres' plane)
  int64_t filled = 0;
  // Filled mask, 0 or 1. Image axes: X section -> (y right, z up), Y section -> (x right, z up),
  // Z section -> (x right, y up); "up" means row 0 holds the largest index.
  Image2D<uint8_t> mask;
};
Result<Section> computeSection(const VoxelGrid& grid, const SectionParams& params);
// Filled voxels in one section, without building the image. O(section words).
int64_t sectionCount(const VoxelGrid& grid, Axis axis, int32_t index);

// ---- Skin removal (thesis 5.2.2) ----
// Every filled voxel with at least one empty face neighbour (6-connectivity) is removed at once, decided on the
// configuration before the layer. The depth of a voxel is the layer (1-based) that removes it; the last non-empty
// layer is the core (the thickest region).
//
// One operation for the window and the CLI: computeDepthMap peels as PeelParams say and keeps every voxel's depth;
// DepthMap::peeled(k) gives what k layers leave (the window steps through k, the CLI takes the one it was asked for).
struct PeelParams {
  int32_t layers = 1;  // ignored when all = true
  bool all = false;    // until nothing is left
};
inline constexpr PeelParams kPeelAll{0, true};

struct PeelResult {
  VoxelGrid remaining;
  std::vector<int64_t> removed_per_layer;  // of the layers peeled
  int64_t remaining_count = 0;
  int64_t core_voxels = 0;  // voxels of the last layer peeled (when everything was peeled: the thickest region)
};

class DepthMap {
 public:
  int32_t layers() const { return int32_t(removed_per_layer_.size()); }
  const std::vector<int64_t>& removedPerLayer() const { return removed_per_layer_; }
  int64_t coreVoxels() const { return removed_per_layer_.empty() ? 0 : removed_per_layer_.back(); }
  // True when the peel ran until nothing was left (not stopped by PeelParams::layers).
  bool complete() const { return rest_count_ == 0; }
  // Voxels still present after peeling k layers (k = 0: the original; k >= layers(): empty for a complete map,
  // otherwise what was left after the last layer peeled). O(words x bits of depth), word operations per layer.
  VoxelGrid remainingAfter(int32_t k) const;
  // What peeling k layers (clamped to 0..layers()) leaves, with the voxels each of those layers removed.
  PeelResult peeled(int32_t k) const;
  // Voxels removed by layer k (1-based); the core is removedBy(layers()). Empty outside 1..layers().
  VoxelGrid removedBy(int32_t k) const;
  // Depth of a voxel (0 for empty voxels, and for voxels a map stopped early did not reach).
  int32_t depthAt(int32_t x, int32_t y, int32_t z) const;
  // Bytes held by the depth bit planes and the remainder; the original grid is a snapshot shared with the caller.
  size_t memoryBytes() const;

 private:
  friend Result<DepthMap> computeDepthMap(const VoxelGrid&, const PeelParams&, const ProgressFn&);
  std::vector<int64_t> removed_per_layer_;
  std::vector<VoxelGrid> depth_bits_;  // binary digits of the depth, one grid per bit, least significant first
  VoxelGrid original_;
  VoxelGrid rest_;  // voxels left after the last layer peeled (empty when complete)
  int64_t rest_count_ = 0;
  int64_t original_count_ = 0;
};
// Peels params.layers layers (all with params.all). Cost: per layer, O(words spanned by what is left) (the peel
// tracks the shrinking extent of every row), parallel over Z; memory: two working grids and
// ceil(log2(layers + 1)) bit-plane grids.
Result<DepthMap> computeDepthMap(const VoxelGrid& grid, const PeelParams& params = kPeelAll,
                                 const ProgressFn& progress = {});
// Upper bound on the bytes computeDepthMap holds at its peak for this grid: the bit planes of the deepest possible
// depth (a voxel is never deeper than its distance to the grid's nearest face, so layers <= ceil(min(nx, ny, nz) / 2)),
// plus the two grids of the peel in progress, each at most the grid's own memory. The window shows it and refuses
// past the memory limit.
uint64_t estimateDepthMapBytes(const VoxelGrid& grid);
// One layer of skin removal, for callers that step. O(allocated words), parallel over Z; the input is not modified.
VoxelGrid peelOneLayer(const VoxelGrid& grid, int64_t* removed = nullptr);

// ---- X-ray thickness (thesis 5.2.3) ----
enum class XrayMode { kMin, kMax, kTotal };
const char* xrayModeName(XrayMode m);  // "min", "max", "total"
std::optional<XrayMode> parseXrayMode(const std::string& s);
struct XrayParams {
  Axis axis = Axis::kZ;
  XrayMode mode = XrayMode::kTotal;
};
struct XrayResult {
  Axis axis = Axis::kZ;
  XrayMode mode = XrayMode::kTotal;
  double voxel_size = 1.0;
  std::string units;
  // Per ray: min / max length of the filled runs, or their total, in voxels; 0 where the ray hits nothing.
  // Image axes as for Section.
  Image2D<int32_t> thickness;
  int64_t rays_hit = 0;
  int64_t min = 0, max = 0;  // over rays that hit material
  double mean = 0.0;
};
Result<XrayResult> computeXray(const VoxelGrid& grid, const XrayParams& params);
// The X-ray of a model that arrives a window of Z layers at a time, lowest first (a .vxm file read in windows): the
// same result as computeXray. Memory along Z: two ints per ray (the run in progress and the value so far).
class XrayAccumulator {
 public:
  XrayAccumulator(const Dims& dims, const GridFrame& frame, const XrayParams& params);
  // Adds layers [z0, z1) of `window`, whose layer 0 is the model's layer z_offset, after every layer below them.
  // Along Z the window must also hold the model's layer z0 - 1 (when there is one).
  void add(const VoxelGrid& window, int32_t z0, int32_t z1, int32_t z_offset);
  // Once every layer was added.
  XrayResult result();

 private:
  Dims dims_;
  XrayResult r_;
  std::vector<int32_t> start_, value_;  // along Z: by padded position of each row
};

// What the X-ray's legend says: title, the image axes, values in voxels and model units, the statistics. Drawn by
// io::drawScalarMapFigure for PNG export and by the window as its own text.
ScalarMapLegend xrayLegend(const XrayResult& xray);
// CSV: header "u,v,thickness_voxels,thickness_<units>", one line per ray that hits material.
std::string xrayCsv(const XrayResult& xray);

// ---- Mass properties (thesis 2.6.1) ----
struct MassProperties {
  int64_t filled = 0;
  double volume = 0.0;       // filled * h^3
  glm::dvec3 centroid{0.0};  // of the voxel centres
  glm::dmat3 inertia{0.0};   // about the centroid, unit density, each voxel a solid cube (products negative)
  Box3d bbox;                // outer faces of the filled voxels
  glm::ivec3 bbox_min_ijk{0}, bbox_max_ijk{-1};  // inclusive voxel indices
  // Discretisation bound on |volume - true volume| for a grid made by centre sampling: surface voxels * h^3
  // (every voxel the surface passes through may be wrongly classified).
  double volume_error_bound = 0.0;
};
MassProperties computeMassProperties(const VoxelGrid& grid);

// Mass properties of a model that arrives a window of Z layers at a time (a .vxm file read in windows): the same
// exact integer sums computeMassProperties makes, so the same result, bit for bit.
class MassAccumulator {
 public:
  MassAccumulator();
  ~MassAccumulator();
  MassAccumulator(const MassAccumulator&) = delete;
  MassAccumulator& operator=(const MassAccumulator&) = delete;
  // Adds layers [z0, z1) of `window`, whose layer 0 is the model's layer z_offset. The window must also hold the
  // model's layers just below z0 and above z1 - 1 where the model has them (the surface voxels, for the bound).
  void add(const VoxelGrid& window, int32_t z0, int32_t z1, int32_t z_offset);
  // Of everything added, placed by `frame`.
  MassProperties result(const GridFrame& frame) const;

  struct Sums;  // the exact sums (mass.cpp)

 private:
  std::unique_ptr<Sums> sums_;
};

// Principal moments of inertia (ascending) and their axes (unit vectors, right-handed: axes[2] = axes[0] x axes[1])
// of a symmetric inertia tensor, by Jacobi rotations.
struct PrincipalAxes {
  glm::dvec3 moments{0.0};
  glm::dmat3 axes{1.0};  // axes[i] is the axis of moments[i] (a column of glm's matrix)
};
PrincipalAxes principalAxes(const glm::dmat3& inertia);

// Densities of common engineering materials (kg/m^3), for mass in kg (the model's units must be known).
struct Material {
  const char* name;
  double density_kg_m3;
};
const std::vector<Material>& commonMaterials();
std::optional<double> materialDensity(const std::string& name);  // by name, case-insensitive

// ---- Measure ----
// The first filled voxel on the segment from `from` to `to`, in voxel-index space (voxel (i, j, k) occupies
// [i, i + 1) x [j, j + 1) x [k, k + 1)): what a click in the 3D view points at. Nothing when the segment meets no
// material.
std::optional<glm::ivec3> pickVoxel(const VoxelGrid& grid, const glm::dvec3& from, const glm::dvec3& to);

// ---- Booleans (thesis 7.2) ----
enum class BoolOp { kUnion, kIntersection, kDifference, kXor };  // kXor: symmetric difference
// Both grids must have the same dims and frame (same lattice); otherwise an error says what differs. Grids with
// different boxes on one lattice: booleanParts (vox/analysis/assembly.h).
Result<VoxelGrid> booleanOp(const VoxelGrid& a, const VoxelGrid& b, BoolOp op);

}  // namespace vox
