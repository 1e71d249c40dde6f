// `voxmod info` on a .vxm file too large for memory, read in windows of Z layers (cli/stream_readers.h); the
// section, X-ray and mass over windows are the workflow's (vox/workflow/streamed_analyses.h).
#include "cli/stream_readers.h"

#include <algorithm>

#include "vox/core/surface.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/voxelize/stream.h"

namespace vox::cli {

namespace {

uint64_t memoryLimit(const MeshOptions& options) {
  return options.memory_limit_bytes > 0 ? options.memory_limit_bytes : defaultMemoryLimitBytes();
}

int64_t filledIn(const VoxelGrid& g, int32_t z0, int32_t z1) {
  int64_t n = 0;
  for (int32_t z = z0; z < z1; ++z) n += sectionCount(g, Axis::kZ, z);
  return n;
}

}  // namespace

std::optional<io::VxmHeaderInfo> streamedVxm(const std::string& file, const MeshOptions& options, Output& out) {
  if (io::lowerExtension(file) != ".vxm") return std::nullopt;
  auto h = io::readVxmHeader(file);
  if (!h || estimateGridBytes(h->dims) <= memoryLimit(options)) return std::nullopt;
  warnMeshOnlyOptions(file, options, out);
  if (!options.units.empty()) h->frame.units = options.units;
  out.note(file + ": its " + dimsText(h->dims) + " grid does not fit under the memory limit of " +
           formatBytes(memoryLimit(options)) + ": reading it in windows of " +
           std::to_string(windowLayers(h->dims, options)) + " layers");
  return *h;
}

int32_t windowLayers(const Dims& dims, const MeshOptions& options) {
  return io::layersWithin(dims, std::min(memoryLimit(options) / 4, kMaxSlabBytes));
}

int streamedInfo(const std::string& file, const io::VxmHeaderInfo& h, const MeshOptions& options, Output& out) {
  int64_t filled = 0, surface = 0;
  uint64_t window_bytes = 0;
  const Status read = io::readVxmInWindows(file, windowLayers(h.dims, options), 1, [&](const io::VxmWindow& w) {
    const int32_t z0 = w.core_begin - w.z_offset, z1 = w.core_end - w.z_offset;
    filled += filledIn(w.grid, z0, z1);
    surface += countSurfaceVoxels(w.grid, z0, z1);
    window_bytes = std::max<uint64_t>(window_bytes, w.grid.memoryBytes());
    return Status(Ok{});
  });
  if (!read) return out.fail(read.error());
  const double v = h.frame.voxel_size;
  auto& d = out.data();
  d["file"] = file;
  d["dims"] = {h.dims.nx, h.dims.ny, h.dims.nz};
  d["voxel_size"] = v;
  d["origin"] = jsonVec3(h.frame.origin);
  d["units"] = h.frame.units;
  d["filled"] = filled;
  d["volume"] = double(filled) * v * v * v;
  d["surface_voxels"] = surface;
  d["memory_bytes"] = window_bytes;
  if (!h.frame.source.empty()) d["source"] = h.frame.source;
  d["streamed"] = true;
  out.say(file + ":");
  out.say("  dims        " + std::to_string(h.dims.nx) + " x " + std::to_string(h.dims.ny) + " x " +
          std::to_string(h.dims.nz));
  out.say("  voxel size  " + significant(v) + " " + h.frame.units);
  out.say("  filled      " + std::to_string(filled) + " voxels, volume " + significant(double(filled) * v * v * v));
  out.say("  surface     " + std::to_string(surface) + " voxels");
  out.say("  memory      " + std::to_string(window_bytes >> 10) + " KiB (read in windows of Z layers)");
  return out.finish();
}

}  // namespace vox::cli
