// Mass properties panel (thesis 2.6.1): volume, centroid, inertia tensor and bounding box of the voxel model, with
// unit density. Computed in the background whenever the model changes while the panel is open.
#include <cstdio>
#include <string>
#include <utility>

#include <imgui.h>

#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {

void drawMassPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to see its mass properties.");
    return;
  }
  const MassProperties* m = state.mass.get(state.model_version);
  if (!m) {
    ImGui::TextUnformatted("Computing...");
    return;
  }
  const std::string units = state.model.frame().units;
  const char* u = units == "model" ? "model units" : units.c_str();
  char buf[160];
  wrappedColoured(ImGui::GetStyle().Colors[ImGuiCol_TextDisabled],
                  std::string("Unit density; each voxel a solid cube. Lengths in ") + u + ".");
  if (m->filled == 0) {
    // Nothing to weigh: no centroid, inertia or box exists (never show the sentinels of an empty box).
    ImGui::Spacing();
    ImGui::TextWrapped(
        "The model is empty (%s): it has no volume, centroid, inertia or bounding box.",
        state.doc.model && state.doc.model->peeled > 0 ? "everything was peeled away" : "no voxel is filled");
    return;
  }
  if (beginFactTable("mass")) {
    tableRow("Filled voxels", groupDigits(m->filled));
    std::snprintf(buf, sizeof buf, "%.6g", m->volume);
    tableRow("Volume", buf);
    std::snprintf(buf, sizeof buf, "+/- %.3g", m->volume_error_bound);
    tableRow("Volume bound", buf);
    if (state.doc.mesh && state.doc.model && state.doc.model->peeled == 0 && state.doc.mesh->volume > 0) {
      std::snprintf(buf, sizeof buf, "%.6g", state.doc.mesh->volume);
      tableRow("Mesh volume", buf);
      std::snprintf(buf, sizeof buf, "%+.3f%%", 100.0 * (m->volume - state.doc.mesh->volume) / state.doc.mesh->volume);
      tableRow("Voxels differ", buf);
    }
    tableRow("Box (voxels)", "(" + std::to_string(m->bbox_min_ijk.x) + ", " + std::to_string(m->bbox_min_ijk.y) + ", " +
                                 std::to_string(m->bbox_min_ijk.z) + ") .. (" + std::to_string(m->bbox_max_ijk.x) +
                                 ", " + std::to_string(m->bbox_max_ijk.y) + ", " + std::to_string(m->bbox_max_ijk.z) +
                                 ")");
    ImGui::EndTable();
  }
  // Vectors in columns, one number to a cell, so that no number is broken across lines.
  if (ImGui::BeginTable("vectors", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 90.0f);
    for (const char* axis : {"x", "y", "z"}) ImGui::TableSetupColumn(axis);
    ImGui::TableHeadersRow();
    const glm::dvec3 e = m->bbox.extent();
    const std::pair<const char*, glm::dvec3> rows[] = {
        {"Centroid", m->centroid}, {"Box min", m->bbox.min}, {"Box max", m->bbox.max}, {"Box size", e}};
    for (const auto& [label, v] : rows) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextDisabled("%s", label);
      for (int c = 0; c < 3; ++c) {
        ImGui::TableSetColumnIndex(c + 1);
        ImGui::Text("%.5g", v[c]);
      }
    }
    ImGui::EndTable();
  }
  heading("Inertia tensor about the centroid");
  if (ImGui::BeginTable("inertia", 3, ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_Borders)) {
    for (int r = 0; r < 3; ++r) {
      ImGui::TableNextRow();
      for (int c = 0; c < 3; ++c) {
        ImGui::TableSetColumnIndex(c);
        ImGui::Text("%.5g", m->inertia[c][r]);  // glm is column-major: [column][row]
      }
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Products of inertia are negative (tensor convention).");
  ImGui::TextWrapped(
      "The volume bound counts every surface voxel as possibly misclassified: the true volume of "
      "the meshed part lies within it.");
}

}  // namespace vox::app
