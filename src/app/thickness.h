#pragma once
// The Thickness panel's analyses: distance, local thickness and hot spots of the model computed in the background
// while the panel is open (keyed by the model version, and kept for another version of the same voxels: an operation
// that leaves the solid as it was, or its undo, keeps them),
// the thin walls under the minimum wall (in the background too), and the round skin removal (peel by distance) as an
// undoable change of the model. No ImGui and no GL here.
#include <memory>
#include <string>

#include "app/app_state.h"

namespace vox::app {

// Each frame (updateDocument): asks for the thickness of the model while the Thickness panel is open.
void requestThickness(AppState& state);
// Where the model's version changes (applyPartsScope): the result at hand becomes the model's when it was computed
// from the same voxels (origin and voxel size included) under another version, such as before a split into bodies
// or an undo of it. O(1) per layer the two share, a comparison of the words of the others.
void adoptThickness(AppState& state);
// The result for the model shown, or null while computing (or when it failed or was cancelled).
const ThicknessResult* currentThickness(const AppState& state);
// Stops the computation for this model version; it is not asked for again until "Compute" (retryThickness).
void cancelThickness(AppState& state);
void retryThickness(AppState& state);
// The minimum wall in use (model units): the user's, or a quarter of the maximum thickness.
double minWall(const AppState& state);
// Thin walls under minWall (and the minimum area), found again in the background when either or the model changed;
// null without a thickness or while they are being found.
const Walls* currentThinWalls(AppState& state);
// The mesh the ray thickness can follow: the document's, while the model is its voxelization as it was (not peeled,
// not a scene of parts); null otherwise.
std::shared_ptr<const MeshSource> rayMesh(const AppState& state);
// The ray thickness the views show: when the panel's method is ray and the rays of `r` are cast; else null.
const RayThicknessResult* shownRay(const AppState& state, const ThicknessResult& r);
// The thickness the views show at voxel v of the model (model units; 0 where none): the rays' when shownRay, else
// the local thickness by spheres.
double shownThickness(const AppState& state, const ThicknessResult& r, const glm::ivec3& v);
// Each frame (updateDocument): casts the rays of the thickness shown, in the background, while the Thickness panel
// shows rays and the model is its mesh's voxelization (a job of its own: switching to rays never recomputes the
// distance or the local thickness, and switching back keeps them).
void requestRays(AppState& state);
bool raysComputing(const AppState& state);
const Error* raysError(const AppState& state);
// Stops casting the rays; they are not cast again for this thickness until rays are chosen again.
void cancelRays(AppState& state);
// The thin-wall region and the hot spot last clicked in the panel's lists: null when none was, or when the model or
// the thin walls have changed since.
const ThinWallRegion* selectedRegion(AppState& state);
const HotSpot* selectedHotSpot(const AppState& state);
// Replaces the model by the model without every voxel within `distance` (model units) of the empty space: an
// undoable change labelled "peel 0.5 mm round". Fails, saying why, without a model or for a negative distance.
Status peelDistance(AppState& state, double distance);

}  // namespace vox::app
