// Mass properties panel (thesis 2.6.1): volume, centroid, inertia tensor, principal moments and axes, bounding box,
// each voxel a solid cube. With the model's units and a density (or a common material) it gives the mass in kg and
// the inertia in kg m^2. Computed in the background whenever the model changes while the panel is open.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include <imgui.h>

#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

// Units and density: what turns unit-density volumes into kilograms.
void materialControls(AppState& state) {
  drawUnitsCombo(state, "Model units");
  helpMarker("What the model's coordinates are in. STL files do not say; .vxm files keep what you choose here.");
  MassUi& ui = state.mass_ui;
  ImGui::SetNextItemWidth(120.0f);
  if (widget::BeginCombo("Material", ui.material.c_str())) {
    if (widget::Selectable("unit density", ui.density <= 0.0)) ui = MassUi{};
    for (const Material& m : commonMaterials()) {
      if (widget::Selectable(m.name, ui.material == m.name)) ui = MassUi{m.name, m.density_kg_m3};
    }
    if (widget::Selectable("custom", ui.material == "custom"))
      ui = MassUi{"custom", ui.density > 0 ? ui.density : 1000.0};
    ImGui::EndCombo();
  }
  if (ui.density <= 0.0) return;  // unit density: no kg/m^3 to show
  ImGui::SetNextItemWidth(120.0f);
  if (widget::InputDouble("kg/m^3", &ui.density, 0.0, 0.0, "%.6g")) {
    ui.density = std::max(ui.density, 0.0);
    ui.material = ui.density > 0.0 ? "custom" : "unit density";
  }
}

void vectorTable(const char* id, std::initializer_list<std::pair<const char*, glm::dvec3>> rows, double f,
                 std::array<const char*, 3> columns = {"x", "y", "z"}) {
  // One number to a cell, so that no number is broken across lines.
  if (!ImGui::BeginTable(id, 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame)) return;
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 90.0f);
  for (const char* c : columns) ImGui::TableSetupColumn(c);
  ImGui::TableHeadersRow();
  for (const auto& [label, v] : rows) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", label);
    for (int c = 0; c < 3; ++c) {
      ImGui::TableSetColumnIndex(c + 1);
      ImGui::Text("%.5g", v[c] * f);
    }
  }
  ImGui::EndTable();
}

}  // namespace

void drawMassPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to see its mass properties.");
    return;
  }
  materialControls(state);
  const MassProperties* m = state.mass.get(state.model_version);
  if (!m) {
    ImGui::TextUnformatted("Computing...");
    return;
  }
  if (m->filled == 0) {  // nothing to weigh: no centroid, inertia or box exists (never the sentinels of an empty box)
    ImGui::TextWrapped(
        "The model is empty (%s): it has no volume, centroid, inertia or bounding box.",
        state.doc.model && state.doc.model->peeled > 0 ? "everything was peeled away" : "no voxel is filled");
    return;
  }
  const std::string units = unitsLabel(state.model.frame().units);
  const double metres = metresPerUnit(state.model.frame().units), density = state.mass_ui.density;
  const bool kg = metres > 0.0 && density > 0.0;
  if (density > 0.0 && metres == 0.0) wrappedColoured(kWarningColour, "Choose the model's units for a mass in kg.");
  char buf[160];
  if (beginFactTable("mass")) {
    tableRow("Filled voxels", groupDigits(m->filled));
    std::snprintf(buf, sizeof buf, "%.6g %s^3", m->volume, units.c_str());
    tableRow("Volume", buf);
    std::snprintf(buf, sizeof buf, "+/- %.3g %s^3", m->volume_error_bound, units.c_str());
    tableRow("Volume bound", buf);
    if (kg) {
      std::snprintf(buf, sizeof buf, "%.6g kg", m->volume * std::pow(metres, 3.0) * density);
      tableRow("Mass", buf);
    }
    if (state.doc.mesh && state.doc.model && state.doc.model->peeled == 0 && state.doc.mesh->volume > 0) {
      std::snprintf(buf, sizeof buf, "%.6g (voxels %+.3f%%)", state.doc.mesh->volume,
                    100.0 * (m->volume - state.doc.mesh->volume) / state.doc.mesh->volume);
      tableRow("Mesh volume", buf);
    }
    ImGui::EndTable();
  }
  vectorTable("vectors", {{"Centroid", m->centroid}, {"Box min", m->bbox.min}, {"Box max", m->bbox.max}}, 1.0);
  const double f = kg ? density * std::pow(metres, 5.0) : 1.0;
  heading(kg ? "Inertia about the centroid (kg m^2)" : "Inertia about the centroid (unit density)");
  vectorTable("inertia",
              {{"", m->inertia[0]}, {"", m->inertia[1]}, {"", m->inertia[2]}},  // symmetric: columns are rows
              f);
  const PrincipalAxes p = principalAxes(m->inertia);
  heading("Principal moments and axes");
  vectorTable("moments", {{"Moments", p.moments}}, f, {"1", "2", "3"});
  vectorTable("axes", {{"Axis 1", p.axes[0]}, {"Axis 2", p.axes[1]}, {"Axis 3", p.axes[2]}}, 1.0);
  wrappedColoured(ImGui::GetStyle().Colors[ImGuiCol_TextDisabled],
                  "Lengths in " + units + ". Products of inertia are negative (tensor convention).");
}

}  // namespace vox::app
