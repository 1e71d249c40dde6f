// The Voxelize dialog: resolution or voxel size, fill mode and units, the plan before starting (voxelize_plan.cpp)
// and the Voxelize and Cancel buttons.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

const char* modeHelp(FillMode m) {
  switch (m) {
    case FillMode::kAuto:
      return "nonzero for closed meshes, vote for broken ones";
    case FillMode::kParity:
      return "odd number of crossings along +X (the thesis)";
    case FillMode::kNonzero:
      return "winding number: overlapping closed bodies become their union";
    case FillMode::kVote:
      return "parity along X, Y and Z, majority per voxel: for meshes with holes";
  }
  return "";
}

// Resolution (a preset or any number of voxels on the longest axis) or a voxel size in model units.
void resolutionChoice(VoxelizeDialog& d, const MeshSource& mesh) {
  VoxelizeParams& p = d.params;
  int by_size = d.by_voxel_size ? 1 : 0;
  widget::RadioButton("Resolution", &by_size, 0);
  ImGui::SameLine();
  widget::RadioButton("Voxel size", &by_size, 1);
  d.by_voxel_size = by_size == 1;
  if (!d.by_voxel_size) {
    p.voxel_size = 0.0;
    for (int64_t preset : {100, 200, 400, 1000}) {
      char label[16];
      std::snprintf(label, sizeof label, "%" PRId64, preset);
      if (widget::RadioButton(label, p.resolution == preset)) p.resolution = preset;
      ImGui::SameLine();
    }
    ImGui::SetNextItemWidth(110.0f);
    int res = int(p.resolution);
    if (widget::InputInt("voxels on the longest axis", &res, 10, 100))
      p.resolution = std::clamp(res, 1, kMaxResolution);
  } else {
    if (p.voxel_size <= 0.0) {
      const glm::dvec3 e = mesh.mesh.bounds().extent();
      p.voxel_size = std::max({e.x, e.y, e.z}) / double(std::max<int64_t>(p.resolution, 1));
    }
    ImGui::SetNextItemWidth(160.0f);
    widget::InputDouble("model units per voxel", &p.voxel_size, 0.0, 0.0, "%.6g");
  }
}

void modeAndUnits(VoxelizeParams& p) {
  ImGui::SetNextItemWidth(160.0f);
  if (widget::BeginCombo("Fill mode", fillModeName(p.mode))) {
    for (FillMode m : kFillModes) {
      if (widget::Selectable(fillModeName(m), m == p.mode)) p.mode = m;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", modeHelp(m));
    }
    ImGui::EndCombo();
  }
  ImGui::TextDisabled("%s", modeHelp(p.mode));
  ImGui::SetNextItemWidth(160.0f);
  if (widget::BeginCombo("Units", unitsLabel(p.units).c_str())) {
    for (std::string_view u : kLengthUnits) {
      if (widget::Selectable(unitsLabel(u).c_str(), u == p.units)) p.units = std::string(u);
    }
    ImGui::EndCombo();
  }
  helpMarker("What the mesh's coordinates are in (STL files do not say): for masses in kg and lengths in mm.");
  if (metresPerUnit(p.units) == 0.0) {
    wrappedColoured(kWarningColour, "This file does not say what its numbers are in: choose the units above.");
  }
}

void voxelizeButtons(AppState& state, const VoxelizeParams& p, bool can_start) {
  ImGui::Spacing();
  if (!can_start) ImGui::BeginDisabled();
  if (widget::Button("Voxelize", ImVec2(120.0f, 0.0f)) ||
      (can_start && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false))) {
    // Voxelizing replaces the model (and the parts split from it): asked first when something is unsaved.
    runBetweenFrames(state, "Voxelize",
                     [p](AppState& s) { guardUnsaved(s, [p](AppState& t) { startVoxelize(t, p); }); });
    ImGui::CloseCurrentPopup();
  }
  if (!can_start) ImGui::EndDisabled();
  ImGui::SameLine();
  if (widget::Button("Cancel", ImVec2(120.0f, 0.0f)) ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
}

}  // namespace

void drawVoxelizeDialog(AppState& state) {
  VoxelizeDialog& d = state.voxelize;
  if (d.open_requested) {
    d.open_requested = false;
    if (state.doc.mesh) {
      proposeResolution(state);
      ImGui::OpenPopup("Voxelize");
    }
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Voxelize", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (!state.doc.mesh || state.close_dialogs) {  // the mesh went away (another file was opened), or a script closes
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  const MeshSource& mesh = *state.doc.mesh;
  ImGui::Text("%s: %s triangles", mesh.path.filename().string().c_str(),
              groupDigits(int64_t(mesh.mesh.triangles.size())).c_str());
  ImGui::Spacing();

  resolutionChoice(d, mesh);
  modeAndUnits(d.params);
  const bool can_start = drawVoxelizePlan(state, d, mesh);
  voxelizeButtons(state, d.params, can_start);
  ImGui::EndPopup();
}

}  // namespace vox::app
