#pragma once
// Operations between the parts of an assembly, all on one lattice (vox/core/lattice.h; docs/conventions.md,
// "Assemblies"): connected components of one model, Booleans between parts with different boxes, interference
// (which parts share voxels, how many, where) and clearance (the smallest gap between two parts that do not touch).
// Every operation is word operations on rows of 64 voxels, shifted where two parts' boxes start at different X.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/lattice.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// ---- Connected components of one voxel model ----
enum class Connectivity { kFace = 6, kAll = 26 };  // face neighbours only, or faces, edges and corners
struct Component {
  int64_t voxels = 0;
  glm::ivec3 box_min{0}, box_max{0};  // voxel indices of the grid, inclusive
};
struct Components {
  std::vector<Component> components;  // largest first (ties: the one whose first voxel comes first, z then y then x)
  // The runs of filled voxels (row y, layer z, voxels [x0, x1)) and the component of each, index into components.
  struct Run {
    int32_t y, z, x0, x1;
  };
  std::vector<Run> runs;
  std::vector<uint32_t> run_component;
};
// Union-find over the runs of filled voxels of each row (a run joins the runs it touches in the row below and the
// layer below: overlapping x for 6-connectivity, x within one voxel and the diagonal rows too for 26). O(words +
// runs); about 24 bytes per run.
Components findComponents(const VoxelGrid& grid, Connectivity connectivity = Connectivity::kFace);
// Component `i` of `grid` alone, as a grid of the same dims and frame.
VoxelGrid componentGrid(const VoxelGrid& grid, const Components& components, size_t i);

// ---- Booleans between parts on one lattice ----
enum class PartOp { kUnion, kIntersection, kDifference, kXor };
const char* partOpName(PartOp op);  // "union", "intersection", "difference", "xor"
std::optional<PartOp> parsePartOp(const std::string& s);
// a op b, covering the union of both boxes (so the result, a and b share one frame of reference whatever the
// operation). Both must lie on the same lattice (the caller checked it; their frames' units must agree). Word
// operations on shifted rows; when the boxes are equal, layers only one operand has are shared, not copied.
LatticeGrid booleanParts(const LatticeGrid& a, const LatticeGrid& b, PartOp op, const Lattice& lattice);

// ---- The union of many parts ----
// The union of `parts` over `box` (lattice voxels), on the lattice's frame at box.min: each part's voxels inside the
// box ORed in row by row over the part's own box. O(words of the parts' rows inside the box), in parallel over layers;
// layers no part reaches stay unallocated. (Booleans one part at a time would write the whole box once per part.)
LatticeGrid unionOfParts(std::span<const LatticeGrid> parts, const Box3i& box, const Lattice& lattice);
// `acc`'s voxels inside `region` (clipped to acc's box) made the union of `parts` there again, the others left as
// they are: when `acc` was the union of the parts and they changed only inside `region` (a part moved: call it for
// its old box and its new one), `acc` is their union again. Only the layers the region reaches are written (copied
// first when they are shared with another grid). O(region rows + words of the parts' rows inside the region).
void redoUnionIn(LatticeGrid& acc, std::span<const LatticeGrid> parts, const Box3i& region);

// ---- Interference ----
struct InterferencePair {
  int32_t a = 0, b = 0;  // part indices, a < b
  int64_t voxels = 0;    // voxels inside both
  Box3i box;             // lattice voxels, the smallest box holding the shared voxels
  glm::dvec3 centre{0};  // model units: the mean of the shared voxels' centres
  // Model units: how thick the overlap is, (2 d - 1) voxels where d is the largest exact distance (voxels) of a shared
  // voxel from the voxels not shared: a sheet k voxels thick reads k voxels (k odd) or k - 1 (k even). Parts that
  // only touch overlap in a sheet a voxel or two thick; a contact tolerance compares with this.
  double thickness = 0.0;
};
struct Interference {
  std::vector<InterferencePair> pairs;  // every pair sharing a voxel, most voxels first (ties: by a, then b)
  int64_t overlap_voxels = 0;           // voxels inside two or more parts
  int64_t multiple_overlap_voxels = 0;  // voxels inside three or more parts
  Box3i multiple_overlap_box;           // where those lie (empty when none)
  int64_t candidate_pairs = 0;          // pairs whose boxes meet (the only ones compared voxel by voxel)
};
// Whether the pair only touches: its overlap at most `contact` thick (model units; 0: never).
inline bool isContact(const InterferencePair& pair, double contact) {
  return contact > 0.0 && pair.thickness <= contact;
}
// Every pair of parts sharing voxels. Boxes are swept along X (sorted by box start), so pairs whose boxes do not meet
// are never compared; the others are compared word by word over the rows of their boxes' intersection. The voxels in
// two or more (three or more) parts are counted by a bit-sliced counter over the union of the boxes, one layer at a
// time. Cost: about one union of all parts plus the common boxes of the pairs that meet; parallel over layers.
Interference findInterference(std::span<const LatticeGrid> parts, const Lattice& lattice);
// As above, reporting progress (the pairs compared, then the layers counted) and stopping with ErrorCode::kCancelled
// as soon as `progress` returns false.
Result<Interference> findInterference(std::span<const LatticeGrid> parts, const Lattice& lattice,
                                      const ProgressFn& progress);
// The voxels a and b share (empty grid over their boxes' intersection, or a 1-voxel empty grid when they do not meet).
LatticeGrid sharedVoxels(const LatticeGrid& a, const LatticeGrid& b, const Lattice& lattice);
// InterferencePair::thickness of the voxels `shared` (model units; 0 when none): the exact distance transform of the
// shared voxels alone (vox/analysis/distance.h), with its progress and cancel.
Result<double> overlapThickness(const LatticeGrid& shared, const Lattice& lattice, const ProgressFn& progress = {});

// ---- Clearance ----
struct Clearance {
  bool touching = false;  // the parts share a voxel, or a voxel of one shares a face with a voxel of the other
  // Distance between the centres of the two closest voxels (one in each part), model units, and the same in voxels.
  double centre_distance = 0.0;
  double centre_distance_voxels = 0.0;
  // The gap: centre distance minus one voxel (the material of the two voxels reaches half a voxel from each centre
  // towards the other along an axis), never below 0. Model units.
  double gap = 0.0;
  glm::ivec3 voxel_a{0}, voxel_b{0};  // lattice voxels realising it
  glm::dvec3 centre_a{0}, centre_b{0};
  bool found = false;  // false when a part is empty or no voxel of b lies within `max_distance`
};
struct ClearanceParams {
  // Search bound, model units (0: the whole union of the two boxes). Gaps beyond it are reported as not found.
  double max_distance = 0.0;
};
// The closest pair of voxels between a and b: the exact Euclidean distance transform of a (vox/analysis/distance.h,
// on the union of the two boxes grown by the bound) read at b's voxels, then the voxel of a nearest to the best one.
// O(voxels of the grown box). Fails with kLimit when the box would need more memory than the machine allows.
// `progress` gets the fraction done (the distance transform's) and cancels with kCancelled when it returns false.
Result<Clearance> findClearance(const LatticeGrid& a, const LatticeGrid& b, const Lattice& lattice,
                                const ClearanceParams& params = {}, const ProgressFn& progress = {});

}  // namespace vox
