// Model panel: what is open (mesh facts, voxel model facts, timings) and how it is drawn.
#include <cmath>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {
namespace {

void meshSection(const AppState& state) {
  const MeshSource& m = *state.doc.mesh;
  heading("Mesh");
  if (beginFactTable("mesh")) {
    tableRow("File", m.format + (m.file_units.empty() ? "" : ", unit " + m.file_units));
    tableRow("Triangles", groupDigits(int64_t(m.mesh.triangles.size())));
    if (m.bodies.size() > 1) tableRow("Bodies", groupDigits(int64_t(m.bodies.size())));
    if (m.deflection > 0) tableRow("Tessellated within", formatLength(m.deflection, m.units));
    const MeshTopology& t = m.topology;
    tableRow("Watertight", t.watertight()               ? std::string("yes")
                           : t.closes_when_noise_welded ? "yes, once exporter noise is welded"
                                                        : "no: " + groupDigits(t.boundary_edges) + " boundary, " +
                                                              groupDigits(t.nonmanifold_edges) + " non-manifold edges");
    if (t.degenerate_triangles > 0) tableRow("Degenerate", groupDigits(t.degenerate_triangles) + " triangles");
    if (t.inconsistent_edges > 0) tableRow("Mixed winding", groupDigits(t.inconsistent_edges) + " edges");
    const glm::dvec3 e = m.mesh.bounds().extent();
    char size[96];
    std::snprintf(size, sizeof size, "%.4g x %.4g x %.4g", e.x, e.y, e.z);
    tableRow("Size", std::string(size) + (m.units == "model" ? "" : " " + m.units));
    char vol[48];
    std::snprintf(vol, sizeof vol, "%.5g", m.volume);
    tableRow("Mesh volume", vol);
    tableRow("Read in", formatSeconds(m.load_s));
    ImGui::EndTable();
  }
  for (const std::string& w : m.warnings) wrappedColoured(kWarningColour, w);
  for (const std::string& n : m.notes) wrappedColoured(ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], n);
}

void modelSection(AppState& state) {
  const ModelSnapshot& snap = *state.doc.model;
  const VoxelGrid& g = state.model;
  heading("Voxel model");
  drawUnitsPrompt(state, "Lengths are shown in model units, and masses need them: say what they are.");
  if (beginFactTable("model")) {
    tableRow("Dimensions", std::to_string(g.nx()) + " x " + std::to_string(g.ny()) + " x " + std::to_string(g.nz()) +
                               " (" + groupDigits(g.dims().count()) + ")");
    tableRow("Voxel size", formatLength(g.voxelSize(), g.frame().units));
    const SurfaceStats* stats = state.surface_stats.get(state.model_version);
    const double h3 = g.voxelSize() * g.voxelSize() * g.voxelSize();
    if (stats) {
      tableRow("Filled voxels", groupDigits(stats->filled));
      tableRow("Surface voxels", groupDigits(stats->surface_voxels));
      char vol[64];
      std::snprintf(vol, sizeof vol, "%.5g (filled x voxel size^3)", double(stats->filled) * h3);
      tableRow("Volume", vol);
      if (stats->suspect_voxels > 0) {
        tableRow("Suspect voxels", groupDigits(stats->suspect_voxels) + " (4-5 free faces)");
        termMarker(state, "suspect-voxels");
      }
    } else {
      tableRow("Filled voxels", "counting...");
    }
    tableRow("Memory", formatBytes(g.memoryBytes()) + " (" + std::to_string(g.allocatedLayers()) + " layers)");
    if (snap.origin) {
      const ModelOrigin& o = *snap.origin;
      tableRow("Made by", o.what);
      if (!o.mode_used.empty()) tableRow("Fill mode", o.mode_used + ": " + o.mode_reason);
      if (o.load_s > 0) tableRow("Read in", formatSeconds(o.load_s));
      if (o.voxelize_s > 0) tableRow("Voxelized in", formatSeconds(o.voxelize_s));
    }
    if (snap.peeled > 0) tableRow("Skin removed", std::to_string(snap.peeled) + " layers (Skin panel)");
    tableRow("Saved", state.doc.save_path.empty() ? "not yet"
                      : hasUnsavedChanges(state)  ? "changed since " + state.doc.save_path.filename().string()
                                                  : state.doc.save_path.filename().string());
    ImGui::EndTable();
  }
  if (snap.origin) {
    for (const std::string& w : snap.origin->warnings) wrappedColoured(kWarningColour, w);
    if (snap.origin->disputed) {
      ImGui::Text("Disputed voxels (vote mode): %s", groupDigits(snap.origin->disputed_count).c_str());
      helpMarker(
          "Vote mode casts rays along X, Y and Z and keeps a voxel when at least two agree. Disputed voxels are where "
          "the three disagreed: usually next to holes in the mesh.");
      if (snap.origin->disputed_count > 0)
        actionCheckbox(state, ActionId::kViewDisputed, "Show disputed voxels in the 3D view");
    }
  }
}

void viewSection(AppState& state) {
  heading("Display");
  if (widget::RadioButton("Classic (thesis table)", !state.view.lit)) setToggle(state, ActionId::kViewLit, false);
  ImGui::SameLine();
  if (widget::RadioButton("Lit", state.view.lit)) setToggle(state, ActionId::kViewLit, true);
  actionCheckbox(state, ActionId::kViewRound, "Round points");
  helpMarker("Thesis 6.2 'point smooth': draws each voxel as a disc instead of a square.");
  bool auto_size = state.view.point_size_px <= 0.0f;
  if (widget::Checkbox("Automatic point size", &auto_size)) state.view.point_size_px = auto_size ? 0.0f : 3.0f;
  helpMarker(
      "Automatic: each point is as large as a voxel appears on screen (times sqrt 2), so the surface stays "
      "closed at any zoom.");
  if (!auto_size) widget::SliderFloat("Point size (px)", &state.view.point_size_px, 1.0f, 16.0f, "%.0f");
  actionCheckbox(state, ActionId::kViewLod, "Coarser points while moving");
  helpMarker(
      "While the view or a slider is dragged, draw a 2x, 4x ... downsampled model so the software renderer "
      "keeps up; the full model is drawn when the mouse is released.");
}

}  // namespace

void drawModelPanel(AppState& state) {
  if (state.doc.path.empty()) {
    ImGui::TextWrapped(
        "No file is open. Use File > Open, drop an STL, .vxm or .binvox file on the window, or pick "
        "one under File > Open Recent.");
    if (widget::Button("Open...")) dispatch(state, ActionId::kOpen);
    viewSection(state);
    return;
  }
  ImGui::TextUnformatted(state.doc.path.filename().string().c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", state.doc.path.string().c_str());
  if (state.doc.mesh) meshSection(state);
  if (state.doc.mesh) {
    if (widget::Button(state.doc.model ? "Voxelize again..." : "Voxelize...")) dispatch(state, ActionId::kVoxelize);
  }
  if (state.doc.model) modelSection(state);
  viewSection(state);
}

}  // namespace vox::app
