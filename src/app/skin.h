#pragma once
// Skin removal: peeling outer layers off the model's base with its depth map, and the memory the depth map may
// take. No ImGui and no GL here.
#include <cstdint>
#include <string>

#include "app/app_state.h"

namespace vox::app {

// Skin removal: show the model with `layers` outer layers removed from its base (0 = the base). Needs the depth
// map; asked for before it is ready, the peel is queued and happens when it arrives.
void peelTo(AppState& state, int32_t layers);
// Stops computing the skin layers of the model's base; they are not asked for again until computeSkinLayers (or a
// peel) asks. A queued peel is dropped.
void cancelSkinLayers(AppState& state);
void computeSkinLayers(AppState& state);
int32_t peelLayersAvailable(const AppState& state);  // layers of the base's depth map; -1 while unknown
const DepthMap* currentDepthMap(const AppState& state);
// The memory the skin layers may use (80% of physical memory), and why they would not fit for this grid (empty when
// they do): the depth map's estimate (estimateDepthMapBytes) plus the model itself.
uint64_t skinLayersMemoryLimit();
std::string skinLayersMemoryProblem(const VoxelGrid& grid);

}  // namespace vox::app
