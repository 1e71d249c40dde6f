// Planning a solid voxelization, before any ray is cast: the fill mode's names, which mode auto resolves to and
// why, the grid placement, and the memory the results need against the limit in force (refused before allocating
// anything large).
#include <cmath>
#include <string>

#include "vox/core/text.h"
#include "vox/voxelize/voxelize.h"
#include "voxelize/passes.h"

namespace vox {

const char* fillModeName(FillMode m) {
  switch (m) {
    case FillMode::kAuto:
      return "auto";
    case FillMode::kParity:
      return "parity";
    case FillMode::kNonzero:
      return "nonzero";
    case FillMode::kVote:
      return "vote";
  }
  return "auto";
}

std::optional<FillMode> parseFillMode(const std::string& s) {
  for (FillMode m : kFillModes) {
    if (s == fillModeName(m)) return m;
  }
  return std::nullopt;
}

std::string fillModeNames(const char* separator) {
  std::string names;
  for (FillMode m : kFillModes) names += (names.empty() ? "" : separator) + std::string(fillModeName(m));
  return names;
}

std::vector<std::string> fillModeNameList() {
  std::vector<std::string> names;
  for (FillMode m : kFillModes) names.emplace_back(fillModeName(m));
  return names;
}

namespace voxelize_detail {

namespace {

bool mayVote(FillMode m) { return m == FillMode::kVote || m == FillMode::kAuto; }

}  // namespace

uint64_t estimateResultBytes(const Dims& dims, FillMode m) {
  return estimateGridBytes(dims) + (mayVote(m) ? SparseVoxels::maxBytes(dims) : 0);
}

std::string plural(int64_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

void chooseMode(FillMode requested, const MeshTopology* topology, const std::string& name, VoxelizeResult& result) {
  const std::string edges_text = topology ? plural(topology->boundary_edges, "boundary edge") + ", " +
                                                plural(topology->nonmanifold_edges, "non-manifold edge")
                                          : std::string();
  switch (requested) {
    case FillMode::kAuto: {
      ModeChoice choice = resolveAutoMode(*topology);
      result.mode_used = choice.mode;
      result.mode_reason = std::move(choice.reason);
      break;
    }
    case FillMode::kParity:
    case FillMode::kNonzero:
    case FillMode::kVote:
      result.mode_used = requested;
      result.mode_reason = std::string("requested: ") + fillModeName(requested);
      if (topology && !topology->watertight() && requested != FillMode::kVote) {
        // Say what can go wrong with this kind of defect: holes break single-axis rays, while touching or
        // overlapping bodies (non-manifold edges only) make the rules differ.
        std::string consequence;
        if (topology->boundary_edges > 0) {
          consequence =
              " mode fills or drops whole runs of a row where a ray passes through a hole (vote mode is "
              "meant for open meshes)";
        } else {
          consequence =
              " mode: touching or overlapping bodies (parity leaves overlaps empty, nonzero fills the "
              "union)";
        }
        result.warnings.push_back(name + " is not watertight (" + edges_text + "); " + fillModeName(requested) +
                                  consequence);
      }
      break;
  }
}

Status checkMemoryLimit(const VoxelizePlan& plan, const VoxelizeParams& params, FillMode mode) {
  const Dims dims = plan.placement.dims;
  const bool vote = mode == FillMode::kVote;
  const uint64_t need = estimateResultBytes(dims, mode);
  if (need > plan.limit_bytes) {
    std::string msg = "a " + dimsText(dims) + " grid (resolution " + std::to_string(plan.placement.resolution) +
                      ") needs about " + formatBytes(need);
    if (vote) {
      msg += " in vote mode (" + formatBytes(estimateGridBytes(dims)) + " for the voxels, up to " +
             formatBytes(SparseVoxels::maxBytes(dims)) + " for the disputed voxels)";
    }
    msg += ", more than the memory limit of " + formatBytes(plan.limit_bytes);
    msg += params.memory_limit_bytes > 0 ? " (as set)" : " (80% of physical memory)";
    msg += "; use a lower resolution";
    if (vote) msg += " or parity/nonzero mode on a closed mesh";
    return makeError(ErrorCode::kLimit, msg);
  }
  return Ok{};
}

}  // namespace voxelize_detail

using voxelize_detail::estimateResultBytes;
using voxelize_detail::plural;

Result<VoxelizePlan> planVoxelization(const Box3d& bounds, const VoxelizeParams& params) {
  if (!(params.voxel_size >= 0.0) || !std::isfinite(params.voxel_size)) {
    return makeError(ErrorCode::kInvalidArgument, "voxel size must be a positive number (or 0 to use the resolution)");
  }
  if (params.threads < 0) {
    return makeError(ErrorCode::kInvalidArgument,
                     "threads must be 0 (all hardware threads) or positive, not " + std::to_string(params.threads));
  }
  auto placement = params.placement          ? Result<GridPlacement>(*params.placement)
                   : params.voxel_size > 0.0 ? placeGridByVoxelSize(bounds, params.voxel_size)
                                             : placeGridByResolution(bounds, params.resolution);
  if (!placement) return placement.error();
  VoxelizePlan plan;
  plan.placement = std::move(placement).value();
  plan.bytes = estimateResultBytes(plan.placement.dims, params.mode);
  plan.limit_bytes = params.memory_limit_bytes > 0 ? params.memory_limit_bytes : defaultMemoryLimitBytes();
  return plan;
}

ModeChoice resolveAutoMode(const MeshTopology& topology) {
  const std::string edges_text =
      plural(topology.boundary_edges, "boundary edge") + ", " + plural(topology.nonmanifold_edges, "non-manifold edge");
  if (topology.watertight()) return {FillMode::kNonzero, "mesh is closed (" + edges_text + "): using nonzero"};
  if (topology.closedOriented()) {
    // Closed bodies that touch or overlap (an assembly): every edge is used as often in each direction, so the
    // winding number is exact everywhere and nonzero gives the union, where vote would equal parity and leave the
    // overlaps empty.
    return {FillMode::kNonzero, "mesh is not manifold (" + edges_text +
                                    ") but closed: every edge is used equally often in both directions (touching or "
                                    "overlapping bodies): using nonzero, which fills their union"};
  }
  if (topology.closes_when_noise_welded) {
    // Open only by exporter noise (corners that should coincide differ by ~1e-17): closed once vertices within 1e-9
    // of the bounding-box diagonal are welded. A ray slips through such a seam only if it passes within that
    // distance of it, so nonzero gives the closed solid (on featuretype it matches the reference exactly), where
    // vote would cost three ray passes for nothing.
    return {FillMode::kNonzero, "mesh is not watertight by exact vertex equality (" + edges_text +
                                    ") but closes when vertices within 1e-9 of its size are welded: using nonzero"};
  }
  return {FillMode::kVote, "mesh is not watertight (" + edges_text + "): using vote"};
}

}  // namespace vox
