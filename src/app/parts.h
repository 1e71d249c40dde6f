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
#include <vector>

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
// Shows or hides part i in the 3D view: an undo step ("hide body 3") that keeps the model version (the voxels and
// what is derived from them stay; the model is not unsaved by it).
void setPartVisible(AppState& state, size_t i, bool visible);
// Clicking part i: selects it alone, or (additive) adds it to or removes it from the selection.
void selectPart(AppState& state, size_t i, bool additive);
// Section, X-ray and mass on the selected part (true) or on the union of all parts.
void setPartsScope(AppState& state, bool selected);
// Makes state.model the union or the selected part, as the scope says (setModel calls it).
void applyPartsScope(AppState& state);

// Moves and turns part i (translation in whole lattice voxels, quarter turns about X, Y, Z; undoable). The model
// grows or shrinks to the parts' new extent; the selection stays. Fails, saying why, for an index out of range.
// The union is made again only over the part's old and new boxes (redoUnionIn): O(the words of the parts' rows in
// those boxes), plus one copy of the union when the extent changes.
Status placePart(AppState& state, size_t i, const PartPlacement& placement);
// Fails, saying why, for a translation (model units) that is not a number or moves a part further than a grid holds.
Status checkTranslation(const AppState& state, double model_units);
// The placement with part i's translation set from model units (snapped to the nearest whole voxel).
PartPlacement placementWithTranslation(const AppState& state, size_t i, const glm::dvec3& model_units);
// The placement with one more quarter turn (+90 degrees) of part i about `axis` (0 X, 1 Y, 2 Z).
PartPlacement placementTurned(const AppState& state, size_t i, int axis);
// Sets part i's colour (RGB in [0, 1], clamped): an undo step ("colour of body 3") that keeps the model version, like
// visibility. `drag`: the change continues a drag in the colour picker, so it joins the step the drag's first change
// made (one undo step for the whole drag) while that step is the current state and was part i's colour; otherwise it
// is a step of its own.
void setPartColour(AppState& state, size_t i, const glm::vec3& colour, bool drag = false);

// Writes every part, placed, as a .vxm file into the folder `dir` (created when missing), named by partFileName
// (numbered as the panel lists them), on the scene's lattice. All the files are written or none (io::saveVoxelFiles).
// Says in the status bar how many files it wrote where.
Status saveParts(AppState& state, const std::filesystem::path& dir);
// The file name part i is saved under: its number from 1 (zero-padded to at least 2 digits), '_', its name without a
// mesh or voxel file extension and with characters that are not letters, digits, ' ', '-', '_' or '.' replaced by
// '_', then ".vxm": "03_body 2.vxm", "02_a.vxm" for a part added from a.stl.
std::string partFileName(const Assembly& parts, size_t i);

// Starts finding the clearance between parts a and b in the background (vox/analysis/assembly.h, findClearance).
void startClearance(AppState& state, size_t a, size_t b);
// The clearance of the two parts it was found for in this model version (null before, or for other parts).
const Clearance* currentClearance(const AppState& state);
// "Gap between body 1 and body 2: 0.35 mm (...)", "... touch", or why it failed, while the two parts it was found
// for are the selection; empty otherwise.
std::string clearanceText(const AppState& state);
// The two voxels realising the clearance in the model's voxel coordinates (for the 3D view's marks), while the two
// parts are the selection; false otherwise or when they touch.
bool clearanceVoxels(const AppState& state, glm::ivec3& a, glm::ivec3& b);

// Starts finding the interference of the current parts in the background (nothing when it is known or running).
void startInterference(AppState& state);
// Stops the interference search; the panel says it was cancelled and offers to start again.
void cancelInterference(AppState& state);
// The interference of the current parts once found (null before).
const Interference* currentInterference(const AppState& state);
// Shows pair i of the interference: both parts selected, their shared voxels drawn in red, the section through
// its centre and the camera on it. -1 clears.
void showInterferencePair(AppState& state, int32_t i);

// "Overlap of body 3 and body 7: 1 234 voxels, shown through the parts" for the pair shown (empty: none).
std::string interferencePairText(const AppState& state);
// The section picture (io::sectionPicture), with the shared voxels of the interference pair shown in red.
ImageRgb partsSectionPicture(const AppState& state, const Section& section);

// Each frame (updateDocument): finished parts, interference and clearance jobs in.
void updateParts(AppState& state);
void updateClearance(AppState& state);  // (updateParts calls it)

// Filled voxels of each part, counted once per model version.
const std::vector<int64_t>& partVoxelCounts(AppState& state);

// ---- Feeders (parts_feeders.cpp): the Casting panel's feeders are parts of the scene, moved, removed and undone
// in the Parts panel like any other. ----
// Adds `feeder` as a part (undoable, "place feeder 2"): its cylinder voxelized on the scene's lattice, named
// "feeder N"; the document becomes a scene first when it is not one. Fails, saying why and changing nothing, for a
// feeder holding no voxel or one making the scene too large.
Status addFeederPart(AppState& state, const Feeder& feeder);
// The indices of the parts that are feeders, in the parts' order (empty without parts).
std::vector<size_t> feederParts(const AppState& state);
// The feeders as placed, in the parts' order.
std::vector<Feeder> placedFeeders(const AppState& state);
// The metal of the casting without its feeders, on the frame of the parts' extent (the model's): the union of the
// parts that are not feeders, or part `only` alone (SIZE_MAX: all).
VoxelGrid castPart(const Assembly& parts, size_t only);

// The union of all parts (unionOfParts), and part i alone, on the frame of the assembly's extent (what the analyses
// use).
VoxelGrid partsUnion(const Assembly& parts);
VoxelGrid partOnExtent(const Assembly& parts, size_t i);

}  // namespace vox::app
