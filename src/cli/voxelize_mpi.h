#pragma once
// voxmod voxelize under mpirun or srun (voxelize_mpi.cpp; docs/conventions.md, "Voxelizing over MPI ranks"): the Z
// slabs of one grid spread over the ranks, slab k to rank k mod N, each voxelized exactly as one process voxelizes
// it and encoded as runs on its rank; rank 0 appends them in slab order to the one .vxm file, written atomically:
// the bytes one process writes.
#include <functional>
#include <string>

#include "cli/model_input.h"

namespace vox::cli {

struct MpiVoxelizeJob {
  std::string mesh_path, out_path;
  bool json = false;
  bool needs_whole_grid = false;  // --remove-strays or --disputed: rank 0 voxelizes alone, in memory
  MeshOptions mesh_options;
};

// Runs `job` over the MPI ranks (MPI_Init to MPI_Finalize); returns this rank's exit code (every rank's is rank 0's).
// What cannot be spread over ranks (a .binvox output, vote mode, a job needing the whole grid) `alone` does on rank 0
// while the others wait. Messages and the JSON object come from rank 0 only; a failure on another rank is reported
// by rank 0 as "rank R: MESSAGE", and leaves no output file (nor a temporary one).
int voxelizeOverMpiRanks(const MpiVoxelizeJob& job, const std::function<int()>& alone);

}  // namespace vox::cli
