// Thickness panel (issue 16): local thickness of the model (the diameter of the largest inscribed ball holding each
// voxel), its statistics and histogram, the thin walls under a minimum wall and the hot spots (the centres of the
// thickest regions, where a casting solidifies last). Computed in the background while the panel is open; the 3D view
// and the section image are coloured by thickness meanwhile.
#include <algorithm>
#include <cfloat>
#include <cstdio>
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

// While computing, after a cancel or a failure: says so; returns the result when there is one.
const ThicknessResult* thicknessOrStatus(AppState& state) {
  if (const ThicknessResult* r = currentThickness(state)) return r;
  if (const Error* e = state.thickness.error(state.model_version)) {
    wrappedColoured(kErrorColour, "Thickness could not be computed: " + e->message);
  } else if (state.thickness_ui.cancelled_version == state.model_version) {
    ImGui::TextUnformatted("Cancelled.");
    if (widget::Button("Compute thickness")) dispatch(state, ActionId::kComputeThickness);
  } else {
    ImGui::TextUnformatted("Computing distance, thickness and hot spots...");
    ImGui::ProgressBar(float(state.thickness.progress()), ImVec2(-1.0f, 0.0f));
    if (widget::Button("Cancel")) dispatch(state, ActionId::kCancelThickness);
    markWidget("thickness_cancel");
  }
  return nullptr;
}

void histogram(const ThicknessStats& st, double min_wall, const std::string& units) {
  std::vector<float> values(st.counts.begin(), st.counts.end());
  const std::string overlay = "voxels per thickness, 0 .. " + formatLength(st.max, units);
  ImGui::PlotHistogram("##thickness_histogram", values.data(), int(values.size()), 0, overlay.c_str(), 0.0f, FLT_MAX,
                       ImVec2(ImGui::GetContentRegionAvail().x, 100.0f));
  markWidget("thickness_histogram");
  if (st.max <= 0.0) return;
  // The minimum wall as a red line on the histogram.
  const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
  const float pad = ImGui::GetStyle().FramePadding.x;
  const float x = r0.x + pad + (r1.x - r0.x - 2.0f * pad) * float(std::min(min_wall / st.max, 1.0));
  ImGui::GetWindowDrawList()->AddLine(ImVec2(x, r0.y), ImVec2(x, r1.y), IM_COL32(255, 60, 60, 255), 2.0f);
}

// The rays, cast as a job of their own once the thickness is known: how many met a wall, or their progress and
// Cancel, or why there are none.
void raysStatus(AppState& state, const ThicknessResult& r) {
  if (const RayThicknessResult* ray = shownRay(state, r)) {
    ImGui::TextDisabled("%s of %s rays met a wall facing back", groupDigits(ray->accepted).c_str(),
                        groupDigits(ray->rays).c_str());
  } else if (raysComputing(state)) {
    ImGui::TextUnformatted("Casting rays (the views show spheres until they are in)...");
    ImGui::ProgressBar(float(state.rays.progress()), ImVec2(-80.0f, 0.0f));
    ImGui::SameLine();
    if (widget::Button("Cancel##rays")) dispatch(state, ActionId::kCancelRays);
  } else if (const Error* e = raysError(state)) {
    wrappedColoured(kWarningColour, "The rays failed: " + e->message);
  } else if (state.thickness_ui.rays_cancelled == r.id) {
    ImGui::TextDisabled("Rays cancelled: the views show spheres.");
    ImGui::SameLine();
    if (widget::SmallButton("Cast rays")) dispatchValues(state, ActionId::kThicknessMethod, {"ray"});
  }
}

// Which thickness the views show: spheres (local thickness) or rays (the mesh's own normals, to the side facing back).
void methodChoice(AppState& state, const ThicknessResult& r) {
  const bool can_ray = rayMesh(state) != nullptr, rays = state.thickness_ui.ray && can_ray;
  ImGui::TextUnformatted("Views show");
  ImGui::SameLine();
  if (widget::RadioButton("spheres", !rays)) dispatchValues(state, ActionId::kThicknessMethod, {"sphere"});
  ImGui::SameLine();
  ImGui::BeginDisabled(!can_ray);
  if (widget::RadioButton("rays", rays)) dispatchValues(state, ActionId::kThicknessMethod, {"ray"});
  ImGui::EndDisabled();
  termMarker(state, "ray-thickness");
  if (!can_ray) {
    helpMarker(
        "Rays follow the mesh the model was voxelized from; a voxel file, a peeled model or a scene of parts "
        "has none.");
  } else if (rays) {
    raysStatus(state, r);
  }
}

}  // namespace

void drawThicknessPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to see its wall thickness.");
    return;
  }
  peeledNotice(state);
  const ThicknessResult* r = thicknessOrStatus(state);
  if (!r) return;
  const ThicknessStats& st = r->thickness.stats;
  const std::string units = state.model.frame().units;

  const Walls* walls = currentThinWalls(state);
  if (beginFactTable("thickness_facts")) {
    // the thinnest wall first: the local thickness's own minimum is a convex edge's, no wall's
    if (walls) {
      tableRow("Thinnest wall", formatLength(walls->wall_min, units));
      termMarker(state, "wall");
    }
    tableRow("Thinnest (sphere)", formatLength(st.min, units));
    termMarker(state, "local-thickness");
    tableRow("Thickest", formatLength(st.max, units));
    tableRow("Mean", formatLength(st.mean, units));
    tableRow("Voxels", groupDigits(st.voxels) + " in " + formatSeconds(r->seconds));
    ImGui::EndTable();
  }
  const double wall = minWall(state);
  histogram(st, wall, units);
  methodChoice(state, *r);

  heading("Minimum wall");
  // applied when the slider is let go: each value on the way would find the walls again
  ThicknessUi& ui = state.thickness_ui;
  float v = ui.wall_drag >= 0.0f ? ui.wall_drag : float(wall);
  ImGui::SetNextItemWidth(-1.0f);
  const std::string fmt = "%.4g " + unitsLabel(units);
  if (widget::SliderFloat("##min_wall", &v, 0.0f, float(st.max), fmt.c_str())) ui.wall_drag = v;
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    dispatchValues(state, ActionId::kMinWall, {std::to_string(v)});
    ui.wall_drag = -1.0f;
  } else if (!ImGui::IsItemActive()) {
    ui.wall_drag = -1.0f;
  }
  markWidget("min_wall_slider");
  if (walls) {
    // walls with less surface are specks: counted, not listed
    double area = walls->min_area;
    ImGui::SetNextItemWidth(120.0f);
    const std::string area_label = "Smallest wall listed, " + unitsLabel(units) + "^2";
    if (widget::InputDouble(area_label.c_str(), &area, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
      dispatchValues(state, ActionId::kMinArea, {std::to_string(area)});
    }
    markWidget("min_area_field");
    drawThinWallList(state, *walls, units);
  } else if (const Error* e = state.thin_walls.error(WallsKey{r->id, wall, state.thickness_ui.min_area})) {
    wrappedColoured(kErrorColour, "The walls could not be found: " + e->message);
  } else {
    ImGui::Text("Finding the walls thinner than %s...", formatLength(wall, units).c_str());
    ImGui::ProgressBar(float(state.thin_walls.progress()), ImVec2(-1.0f, 0.0f));
  }

  heading("Hot spots", state, "hot-spot");
  drawHotSpotList(state, *r, units);
  if (!state.thickness_ui.volume_problem.empty()) {
    wrappedColoured(kWarningColour, state.thickness_ui.volume_problem);
  }
}

}  // namespace vox::app
