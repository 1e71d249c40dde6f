// Mass properties panel (thesis 2.6.1): volume, centroid, inertia tensor and bounding box of the voxel model, with
// unit density. Computed in the background whenever the model changes while the panel is open.
#include <cstdio>
#include <string>

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
  if (beginFactTable("mass")) {
    tableRow("Filled voxels", groupDigits(m->filled));
    std::snprintf(buf, sizeof buf, "%.6g  (+/- %.3g)", m->volume, m->volume_error_bound);
    tableRow("Volume", buf);
    if (state.doc.mesh && state.doc.model && state.doc.model->peeled == 0 && state.doc.mesh->volume > 0) {
      std::snprintf(buf, sizeof buf, "%.6g  (voxels differ by %+.3f%%)", state.doc.mesh->volume,
                    100.0 * (m->volume - state.doc.mesh->volume) / state.doc.mesh->volume);
      tableRow("Mesh volume", buf);
    }
    std::snprintf(buf, sizeof buf, "(%.5g, %.5g, %.5g)", m->centroid.x, m->centroid.y, m->centroid.z);
    tableRow("Centroid", buf);
    if (m->filled > 0) {
      std::snprintf(buf, sizeof buf, "(%.5g, %.5g, %.5g)", m->bbox.min.x, m->bbox.min.y, m->bbox.min.z);
      tableRow("Box min", buf);
      std::snprintf(buf, sizeof buf, "(%.5g, %.5g, %.5g)", m->bbox.max.x, m->bbox.max.y, m->bbox.max.z);
      tableRow("Box max", buf);
      const glm::dvec3 e = m->bbox.extent();
      std::snprintf(buf, sizeof buf, "%.5g x %.5g x %.5g", e.x, e.y, e.z);
      tableRow("Box size", buf);
      std::snprintf(buf, sizeof buf, "(%d, %d, %d) .. (%d, %d, %d)", m->bbox_min_ijk.x, m->bbox_min_ijk.y,
                    m->bbox_min_ijk.z, m->bbox_max_ijk.x, m->bbox_max_ijk.y, m->bbox_max_ijk.z);
      tableRow("Box (voxels)", buf);
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
