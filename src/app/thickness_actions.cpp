// The Thickness entries of the action table (actions.cpp): the panel, the minimum wall and defect area, the method,
// and the lists of thin walls and hot spots (a row shows its place). Row numbers in scripts count from 1, as the panel
// shows them.
#include <algorithm>
#include <cmath>
#include <string>

#include "app/action_functions.h"
#include "app/thickness.h"
#include "app/update.h"  // centreView, axisLength
#include "vox/core/text.h"

namespace vox::app::actions {
void panelThickness(AppState& s) { showPanel(s, Panel::kThickness); }
bool onThickness(const AppState& s) { return s.panel == Panel::kThickness; }
Status minWallAt(AppState& s, const ActionArgs& a) {  // VALUE: the Thickness panel's minimum wall, model units
  double v = 0.0;
  if (!parseNumber(a.words[0], v) || !(v >= 0.0)) return badValues("min-wall takes a length >= 0 in model units");
  s.thickness_ui.min_wall = v;
  showPanel(s, Panel::kThickness);
  return Ok{};
}
Status minAreaAt(AppState& s, const ActionArgs& a) {
  double v = 0.0;
  if (!parseNumber(a.words[0], v) || !std::isfinite(v)) {
    return badValues("min-area takes an area in model units^2 (below 0: the minimum wall squared)");
  }
  s.thickness_ui.min_area = v < 0.0 ? -1.0 : v;
  showPanel(s, Panel::kThickness);
  return Ok{};
}
Status thicknessMethodAt(AppState& s, const ActionArgs& a) {  // VALUE: sphere | ray
  const std::string& m = a.words[0];
  if (m != "sphere" && m != "ray") return badValues("thickness-method takes sphere or ray");
  if (m == "ray" && !rayMesh(s)) {
    return makeError(ErrorCode::kInvalidArgument,
                     "the ray thickness follows the mesh the model was voxelized from: this model has none as it is "
                     "(a voxel file, a peeled model or a scene of parts)");
  }
  s.thickness_ui.ray = m == "ray";
  if (s.thickness_ui.ray) s.thickness_ui.rays_cancelled = 0;  // asked for again: cast after a cancel
  showPanel(s, Panel::kThickness);
  return Ok{};
}

namespace {

// A place in the Thickness panel's lists, voxels lo..hi: the section along its axis through its middle, the 3D view
// turned about it and brought near enough to see it.
void showThicknessPlace(AppState& s, glm::ivec3 lo, glm::ivec3 hi) {
  const int a = int(s.section.axis);
  s.section.index = std::clamp((lo[a] + hi[a]) / 2, 0, std::max(axisLength(s, s.section.axis) - 1, 0));
  const glm::ivec3 size = hi - lo + 1;
  centreView(s, glm::dvec3(lo + hi + 1) * 0.5, double(std::max({size.x, size.y, size.z})));
  s.section.playing = false;
  showPanel(s, Panel::kThickness);
}

// The selection, for `result`: what was selected in another result is dropped.
ThicknessUi& select(ThicknessUi& ui, uint64_t result) {
  if (ui.selected_result != result) ui.selected_region = ui.selected_spot = -1;
  ui.selected_result = result;
  return ui;
}

}  // namespace

Status thinRegionAt(AppState& s, const ActionArgs& a) {
  if (currentThickness(s) && !currentThinWalls(s)) {
    return badValues("thin-region: the walls under the minimum wall are still being found");
  }
  const Walls* thin = currentThinWalls(s);
  const auto i = listRow(a, thin ? thin->regions.size() : 0, "thin-region", "Thickness",
                         "no wall is thinner than the minimum wall");
  if (!i) return i.error();
  const ThinWallRegion& g = thin->regions[*i];
  showThicknessPlace(s, g.bbox_min_ijk, g.bbox_max_ijk);
  select(s.thickness_ui, currentThickness(s)->id).selected_region = int32_t(*i);
  return Ok{};
}

Status hotSpotAt(AppState& s, const ActionArgs& a) {
  const ThicknessResult* r = currentThickness(s);
  const auto i = listRow(a, r ? r->hot_spots.size() : 0, "hot-spot", "Thickness", "the thickness has no hot spot");
  if (!i) return i.error();
  const HotSpot& spot = r->hot_spots[*i];
  const auto reach = int32_t(std::ceil(spot.radius / s.model.voxelSize()));  // its inscribed ball
  showThicknessPlace(s, spot.voxel - reach, spot.voxel + reach);
  select(s.thickness_ui, r->id).selected_spot = int32_t(*i);
  return Ok{};
}

void cancelRaysNow(AppState& s) { cancelRays(s); }
bool raysComputingNow(const AppState& s) { return raysComputing(s); }

}  // namespace vox::app::actions
