#pragma once
// What the Parts panel's files (parts.cpp, parts_feeders.cpp) share: committing new parts as an undoable model state,
// the size check before a scene is made, and the current model as a scene.
#include <memory>
#include <optional>
#include <string>

#include "app/app_state.h"

namespace vox::app {

// A new model state holding `parts`: the union as the model (found here when not given), a new base (the skin layers
// of the union). The selection is cleared.
void commitParts(AppState& state, std::shared_ptr<const Assembly> parts, const std::string& label,
                 std::optional<VoxelGrid> union_of_parts = std::nullopt);
// Refuses, before anything is allocated, a scene whose box would not fit a grid or whose union would take more than
// half the memory a large piece of work may plan for. `what` starts the message ("Moving body 2").
Status checkSceneSize(const Assembly& scene, const std::string& what);
// The current model as an assembly of one part (a document that is not a scene yet), or the current parts.
Assembly sceneOfModel(const AppState& state);

}  // namespace vox::app
