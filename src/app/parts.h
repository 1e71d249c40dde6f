#pragma once
// The document as a scene of parts on one lattice (vox/core/assembly.h; docs/conventions.md, "Assemblies"): splitting
// the model into bodies (a mesh's shells, or a voxel model's connected components), adding a part from a file,
// Booleans between two parts, removing a part, and the interference of all parts. Each change of the parts is a new
// model state (ModelSnapshot::parts), so it is undoable like a peel; the model grid is the union of the parts, or the
// selected part when the Parts panel says so, on the frame of the assembly's extent. No ImGui and no GL here.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "app/app_state.h"
#include "vox/core/result.h"

namespace vox::app {

// The current parts (null when the document is one model).
const Assembly* currentParts(const AppState& state);
bool partsBusy(const AppState& state);  // splitting or adding a part

// Splits the model into parts in the background: a mesh document into its bodies (each voxelized on the model's
// lattice), a voxel model into its connected components (state.parts_ui.connectivity). Needs a model.
void startSplitBodies(AppState& state);
// Adds a mesh or voxel file as a part, in the background: a mesh is voxelized on the scene's lattice, a voxel file
// must share it (else an error saying how they differ). The model becomes a scene first when it is not one.
void startAddPart(AppState& state, const std::filesystem::path& path);
// a op b into a new part (undoable). Fails, saying why, for indices out of range or a == b.
Status partBoolean(AppState& state, PartOp op, size_t a, size_t b);
// Removes part i (undoable); the last part stays.
Status removePart(AppState& state, size_t i);
// Shows or hides part i in the 3D view (not a change of the model).
void setPartVisible(AppState& state, size_t i, bool visible);
// Clicking part i: selects it alone, or (additive) adds it to or removes it from the selection.
void selectPart(AppState& state, size_t i, bool additive);
// Section, X-ray and mass on the selected part (true) or on the union of all parts.
void setPartsScope(AppState& state, bool selected);
// Makes state.model the union or the selected part, as the scope says (setModel calls it).
void applyPartsScope(AppState& state);

// Starts finding the interference of the current parts in the background (nothing when it is known or running).
void startInterference(AppState& state);
// The interference of the current parts once found (null before).
const Interference* currentInterference(const AppState& state);
// Shows pair i of the interference: both parts selected, their shared voxels drawn in red, the section through
// its centre and the camera on it. -1 clears.
void showInterferencePair(AppState& state, int32_t i);

// "Overlap of body 3 and body 7: 1 234 voxels, shown through the parts" for the pair shown (empty: none).
std::string interferencePairText(const AppState& state);
// The section picture (io::sectionPicture), with the shared voxels of the interference pair shown in red.
ImageRgb partsSectionPicture(const AppState& state, const Section& section);

// Each frame (updateDocument): finished parts and interference jobs in.
void updateParts(AppState& state);

// Filled voxels of each part, counted once per model version.
const std::vector<int64_t>& partVoxelCounts(AppState& state);

// The union of all parts, and part i alone, on the frame of the assembly's extent (what the 3D view and the
// analyses use).
VoxelGrid partsUnion(const Assembly& parts);
VoxelGrid partOnExtent(const Assembly& parts, size_t i);

}  // namespace vox::app
