// Skin removal panel (thesis 5.2.2 and 6.4): peel the surface layer by layer down to the core, the thickest
// region. The depth map is computed once per model in the background; every peel step then shows
// DepthMap::remainingAfter(k) at once, and each step is an undoable change of the model.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

void actionButton(AppState& state, ActionId id, const char* label, const char* rect_name, float width) {
  const Action& a = action(id);
  const bool enabled = actionEnabled(state, a);
  if (!enabled) ImGui::BeginDisabled();
  if (widget::Button(label, ImVec2(width, 0.0f))) dispatch(state, id);
  if (!enabled) ImGui::EndDisabled();
  markWidget(rect_name);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    const std::string sc = shortcutText(a.shortcut);
    ImGui::SetTooltip("%s%s%s%s", a.label, sc.empty() ? "" : " (", sc.c_str(), sc.empty() ? "" : ")");
  }
}

// The round peel: every voxel within a distance of the empty space (a layer peel removes by face steps).
void roundPeelRow(AppState& state, const ModelSnapshot& snap, float w) {
  if (state.skin.peel_distance <= 0.0f) state.skin.peel_distance = float(snap.grid.voxelSize());
  ImGui::SetNextItemWidth(w);
  const std::string fmt = "%.4g " + unitsLabel(snap.grid.frame().units);
  widget::InputFloat("##peel_distance", &state.skin.peel_distance, 0.0f, 0.0f, fmt.c_str());
  state.skin.peel_distance = std::max(state.skin.peel_distance, 0.0f);
  ImGui::SameLine();
  if (widget::Button("Peel by distance", ImVec2(2.0f * w + ImGui::GetStyle().ItemSpacing.x, 0.0f))) {
    dispatchValues(state, ActionId::kPeelDistance, {std::to_string(state.skin.peel_distance)});
  }
  markWidget("peel_distance");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Removes every voxel whose centre lies within this distance of the empty space: a round skin of even\n"
        "thickness, where a layer removes face steps (thinner on slopes). Undo (Ctrl+Z) brings it back.");
  }
}

}  // namespace

void drawSkinPanel(AppState& state) {
  if (!state.doc.model) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to peel its skin.");
    return;
  }
  const ModelSnapshot& snap = *state.doc.model;
  const DepthMap* depth = currentDepthMap(state);

  ImGui::TextWrapped(
      "Each layer removes every voxel with a free face (6-connectivity), all at once. The last "
      "layer left is the core: the thickest region of the part.");
  ImGui::Spacing();
  const float w = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3.0f;
  actionButton(state, ActionId::kPeelOne, "Peel one", "peel_one", w);
  ImGui::SameLine();
  actionButton(state, ActionId::kPeelBack, "Back one", "peel_back", w);
  ImGui::SameLine();
  actionButton(state, ActionId::kPeelReset, "Reset", "peel_reset", w);
  actionButton(state, ActionId::kPeelN, ("Peel " + std::to_string(state.skin.peel_count)).c_str(), "peel_n", w);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(w);
  if (widget::InputInt("##peel_n", &state.skin.peel_count))
    state.skin.peel_count = std::clamp(state.skin.peel_count, 1, 100000);
  ImGui::SameLine();
  actionButton(state, ActionId::kPeelCore, "Peel to core", "peel_core", w);

  roundPeelRow(state, snap, w);

  // What peeling will hold, before it starts (the bound the depth map stays under).
  wrappedColoured(ImGui::GetStyle().Colors[ImGuiCol_TextDisabled],
                  "Memory for the skin layers: up to " + formatBytes(estimateDepthMapBytes(snap.base)) + " (limit " +
                      formatBytes(skinLayersMemoryLimit()) + ")");
  if (!depth) {
    ImGui::Spacing();
    if (const Error* e = state.depth.error(snap.base_id)) {
      ImGui::TextWrapped("Skin layers could not be computed: %s", e->message.c_str());
    } else if (state.skin.cancelled_base == snap.base_id) {
      ImGui::TextUnformatted("Cancelled.");
      if (widget::Button("Compute the skin layers")) dispatch(state, ActionId::kSkinLayers);
    } else {
      ImGui::TextUnformatted(state.skin.pending_peel ? "Computing the skin layers; the peel follows..."
                                                     : "Computing the skin layers...");
      ImGui::ProgressBar(float(state.depth.progress()), ImVec2(-1.0f, 0.0f));
      if (widget::Button("Cancel##skin")) dispatch(state, ActionId::kCancelSkinLayers);
    }
    return;
  }

  const std::vector<int64_t>& removed = depth->removedPerLayer();
  const int32_t layers = depth->layers();
  const int32_t k = snap.peeled;
  const int64_t total = std::accumulate(removed.begin(), removed.end(), int64_t(0));
  const int64_t gone =
      std::accumulate(removed.begin(), removed.begin() + std::min<size_t>(size_t(k), removed.size()), int64_t(0));
  const double h = state.model.voxelSize();
  const std::string units = state.model.frame().units;

  heading("Layers");
  if (beginFactTable("skin_facts")) {
    // The CLI's words: the model has L skin layers, the last (layer L) is the core; peeling stops before it.
    tableRow("Skin layers", std::to_string(layers) + " (the core is layer " + std::to_string(layers) + ")");
    termMarker(state, "skin-layer");
    tableRow("Core depth", formatLength(double(layers) * h, units) + " in face steps");
    tableRow("Peeled", k == 0 ? std::string(snap.round_peels.empty() ? "none (the whole model)" : "no layers")
                              : std::to_string(k) + " of " + std::to_string(layers) + " layers" +
                                    (k == layers - 1 ? ": only the core remains" : ""));
    if (!snap.round_peels.empty()) tableRow("Peeled round", snap.round_peels + " before these layers");
    tableRow("Remaining voxels", groupDigits(total - gone) + " of " + groupDigits(total));
    if (k > 0 && size_t(k) <= removed.size()) tableRow("Layer removed", groupDigits(removed[size_t(k) - 1]));
    tableRow("Core voxels", groupDigits(depth->coreVoxels()));
    termMarker(state, "core");
    ImGui::EndTable();
  }

  // Removed voxels per layer; the marker shows how far the model is peeled.
  std::vector<float> values(removed.begin(), removed.end());
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "removed per layer (1..%d)", layers);
  ImGui::PlotHistogram("##removed", values.data(), int(values.size()), 0, overlay, 0.0f, FLT_MAX,
                       ImVec2(ImGui::GetContentRegionAvail().x, 110.0f));
  const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
  markWidget("skin_histogram");
  if (layers > 0 && k > 0) {
    const float pad = ImGui::GetStyle().FramePadding.x;
    const float x = r0.x + pad + (r1.x - r0.x - 2.0f * pad) * float(k) / float(layers);
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, r0.y), ImVec2(x, r1.y), IM_COL32(255, 80, 80, 255), 2.0f);
  }

  widget::Checkbox("Show the core through the model", &state.view.show_core);
  helpMarker(
      "Draws the voxels of the last layer (the thickest region) in magenta over the model, so you can see "
      "where it lies before peeling down to it.");
}

}  // namespace vox::app
