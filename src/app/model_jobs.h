#pragma once
// The background jobs that make the model: voxelizing the open mesh (its plan, a resolution that fits in memory, the
// start and the result), and what it shares with loading (busy, cancel). Opening starts in document.h (startOpen).
// No ImGui and no GL here.
#include <cstdint>

#include "app/app_state.h"

namespace vox::app {

// Voxelizes the open mesh in the background; the current model stays on screen until the new one is ready. A CAD
// file whose open tessellation is coarser than the grid asks (io::cadDeflectionFor) is tessellated again first.
void startVoxelize(AppState& state, const VoxelizeParams& params);
// Memory a voxelization may take without a second thought: 4 GiB, or a quarter of the machine's memory if less.
uint64_t comfortableVoxelizeBytes();
// When the voxelize dialog opens: if the last resolution would need more than that for this mesh, propose the
// largest of 1000, 400, 200, 100 that does not, and say why (VoxelizeDialog::proposal_note).
void proposeResolution(AppState& state);
// The plan (dims, voxel size, memory) for these params, or why they cannot work.
Result<VoxelizePlan> planFor(const AppState& state, const VoxelizeParams& params);
void cancelJobs(AppState& state);
bool modelBusy(const AppState& state);  // loading or voxelizing

// A finished voxelization becomes the model (updateDocument), undoably, with where it came from (mode, reason,
// warnings, disputed voxels, `seconds` it took); a new tessellation it made becomes the document's mesh.
void applyVoxelized(AppState& state, VoxelizeOutcome outcome, const VoxelizeParams& params, double seconds);

}  // namespace vox::app
