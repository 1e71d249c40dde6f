#pragma once
// voxmod voxelize for grids that do not fit under the memory limit: Z slabs voxelized one after another and
// appended to the .vxm file (vox/voxelize/stream.h, vox/io/vxm_stream.h). The JSON object has voxelize's keys and
// also streamed, slabs and slab_layers.
#include <string>

#include "cli/output.h"
#include "vox/io/mesh_file.h"
#include "vox/voxelize/stream.h"
#include "vox/voxelize/voxelize.h"

namespace vox::cli {

struct StreamedVoxelizeJob {
  std::string mesh_path, out_path;
  int32_t slab_layers = 1;
  double t0 = 0.0, t_loaded = 0.0;  // nowSeconds() at the start and once the mesh was read
  std::string reason = "the grid does not fit under the memory limit";  // why in slabs, for the human line
};

// Voxelizes `mesh` into job.out_path (a .vxm file: anything else is refused) and reports it through `out`.
int runStreamedVoxelize(const StreamedVoxelizeJob& job, io::MeshFileLoad& mesh, const VoxelizeParams& params,
                        Output& out);

// The report of a streamed voxelization `done` of `mesh` into job.out_path (written by nowSeconds() `t_written`):
// the human lines, or the JSON object with the keys above, through `out`. Returns out.finish().
int reportStreamedVoxelize(const StreamedVoxelizeJob& job, const io::MeshFileLoad& mesh, const GridFrame& frame,
                           const StreamedVoxelization& done, double t_written, Output& out);

// This process's peak resident memory (getrusage).
int64_t peakRssBytes();

}  // namespace vox::cli
