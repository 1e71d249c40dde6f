#pragma once
// The Print panel's analysis (vox/workflow/print_check.h): overhangs and support along the chosen build direction,
// trapped cavities and, when asked, the build directions ranked by support, computed in the background while the
// panel is open and keyed by the model version, the direction, the angle and whether the directions are searched.
// The overhangs follow the mesh's own normals while the model is its voxelization as it was (rayMesh), else the
// voxels' surface. No ImGui and no GL here.
#include <string>

#include <glm/vec3.hpp>

#include "app/app_state.h"

namespace vox::app {

// Each frame (updateDocument): asks for the printability of the model while the Print panel is open.
void requestPrint(AppState& state);
// What the panel asks for now.
PrintKey wantedPrintKey(const AppState& state);
// The result for the model and choices shown, or null while computing (or when it failed or was cancelled).
const PrintResult* currentPrint(const AppState& state);
bool printComputing(const AppState& state);
bool printCancelled(const AppState& state);
void cancelPrint(AppState& state);
void retryPrint(AppState& state);
// The build direction, "+z" or "0.3, 0.1, 0.95" (vox/analysis/printability.h); kInvalidArgument otherwise.
Status setPrintDirection(AppState& state, const std::string& text);
// Lays the face at surface voxel `voxel` on the plate: the build direction becomes the inward normal there (the
// voxels about it, 5 x 5 x 5, give the normal), snapped to an axis within 10 degrees.
Status layFaceOnPlate(AppState& state, glm::ivec3 voxel);
// The trapped cavity last clicked in the list, or null.
const TrappedCavity* selectedCavity(const AppState& state);

}  // namespace vox::app
