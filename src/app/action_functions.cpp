#include "app/action_functions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "app/measure.h"
#include "app/operations.h"
#include "app/parts.h"
#include "app/print.h"
#include "vox/core/text.h"

namespace vox::app::actions {

Error badValues(std::string message) { return makeError(ErrorCode::kInvalidArgument, std::move(message)); }

Result<size_t> listRow(const ActionArgs& a, size_t count, const std::string& what, const std::string& panel,
                       const std::string& none) {
  if (count == 0) return badValues(what + ": " + none);
  size_t n = 0;
  if (!parseNumber(a.words[0], n) || n < 1 || n > count) {
    return badValues(what + " takes a row of the " + panel + " panel's list, 1 to " + std::to_string(count));
  }
  return n - 1;
}
namespace {

void showPanel(AppState& s, Panel p) {
  s.panel = p;
  s.panel_change_requested = true;
}

void standardView(AppState& s, render::StandardView v) {
  s.view.camera.setStandardView(v);
  s.view.fit_pending = true;
}

void stepSection(AppState& s, int32_t delta) {
  s.section.playing = false;
  s.section.index += delta;  // clamped where the section is computed
  showPanel(s, Panel::kSection);
}

// Peel actions are relative to the layer shown now.
int32_t peeled(const AppState& s) { return s.doc.model ? s.doc.model->peeled : 0; }

// A path for the file browser's purpose, as the browser's Save or Open button gives it (errors become dialogs).
Status acceptPath(AppState& s, BrowserPurpose purpose, const ActionArgs& a) {
  acceptBrowserPath(s, purpose, a.rest);
  return Ok{};
}

}  // namespace

// ---- Conditions ----
bool hasModel(const AppState& s) { return s.doc.model.has_value() && !modelBusy(s); }
bool hasOrphanAutosave(const AppState& s) { return !s.autosave.orphans.empty() && !modelBusy(s); }
bool skinLayersComputing(const AppState& s) { return s.doc.model && s.depth.computing(s.doc.model->base_id); }
bool skinLayersCancelled(const AppState& s) { return s.doc.model && s.skin.cancelled_base == s.doc.model->base_id; }
bool thicknessComputing(const AppState& s) { return s.thickness.computing(s.model_version); }
bool thicknessCancelled(const AppState& s) {
  return s.model_version != 0 && s.thickness_ui.cancelled_version == s.model_version;
}
bool hasMesh(const AppState& s) { return s.doc.mesh != nullptr && !s.load_job.active(); }
bool hasSection(const AppState& s) { return !s.model.empty(); }
// An X-ray export needs the X-ray computed (the X-ray panel computes it); until then the menu item is off.
bool hasXray(const AppState& s) { return currentXray(s) != nullptr; }
bool hasMeasure(const AppState& s) { return !measurePicks(s).empty(); }
bool canPeel(const AppState& s) {
  const int32_t layers = peelLayersAvailable(s);
  return hasModel(s) && (layers < 0 || peeled(s) < layers - 1);
}
bool canPeelBack(const AppState& s) { return hasModel(s) && peeled(s) > 0; }
bool hasDisputed(const AppState& s) {
  return s.doc.model && s.doc.model->origin && s.doc.model->origin->disputed != nullptr;
}

bool canCancel(const AppState& s) {
  return modelBusy(s) || s.thickness.computing(s.model_version) || printComputing(s) || volumeExportRunning(s) ||
         s.parts_job.active() || s.interference_job.active() || s.clearance_job.active() || skinLayersComputing(s);
}
bool hasThickness(const AppState& s) { return currentThickness(s) != nullptr; }
// A depth export needs the skin layers computed (the Skin panel computes them); until then the menu item is off.
bool hasDepth(const AppState& s) { return currentDepthMap(s) != nullptr; }

// ---- File ----
void open(AppState& s) { openBrowser(s, BrowserPurpose::kOpen); }
Status openPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kOpen, a); }
void save(AppState& s) { saveOrAsk(s); }
void saveAs(AppState& s) { openBrowser(s, BrowserPurpose::kSaveModel); }
Status savePath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kSaveModel, a); }
void exportBinvox(AppState& s) { openBrowser(s, BrowserPurpose::kExportBinvox); }
Status exportBinvoxPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportBinvox, a); }
void exportSurface(AppState& s) { openBrowser(s, BrowserPurpose::kExportSurface); }
Status exportSurfacePath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportSurface, a); }
void exportSmoothSurface(AppState& s) { openBrowser(s, BrowserPurpose::kExportSmoothSurface); }
Status exportSmoothSurfacePath(AppState& s, const ActionArgs& a) {
  return acceptPath(s, BrowserPurpose::kExportSmoothSurface, a);
}
void exportView(AppState& s) { openBrowser(s, BrowserPurpose::kExportViewPng); }
Status exportViewPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportViewPng, a); }
void exportSection(AppState& s) { openBrowser(s, BrowserPurpose::kExportSectionPng); }
Status exportSectionPath(AppState& s, const ActionArgs& a) {
  return acceptPath(s, BrowserPurpose::kExportSectionPng, a);
}
void exportXray(AppState& s) { openBrowser(s, BrowserPurpose::kExportXrayPng); }
Status exportXrayPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportXrayPng, a); }
void exportCsv(AppState& s) { openBrowser(s, BrowserPurpose::kExportXrayCsv); }
Status exportCsvPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportXrayCsv, a); }
void exportReport(AppState& s) { openBrowser(s, BrowserPurpose::kExportReport); }
Status exportReportPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportReport, a); }
void exportVolume(AppState& s) { openBrowser(s, BrowserPurpose::kExportVolume); }
Status exportVolumePath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportVolume, a); }
void exportThickness(AppState& s) { openBrowser(s, BrowserPurpose::kExportThickness); }
Status exportThicknessPath(AppState& s, const ActionArgs& a) {
  return acceptPath(s, BrowserPurpose::kExportThickness, a);
}
void exportDepth(AppState& s) { openBrowser(s, BrowserPurpose::kExportDepth); }
Status exportDepthPath(AppState& s, const ActionArgs& a) { return acceptPath(s, BrowserPurpose::kExportDepth, a); }
void exportXrayVolume(AppState& s) { openBrowser(s, BrowserPurpose::kExportXrayVolume); }
Status exportXrayVolumePath(AppState& s, const ActionArgs& a) {
  return acceptPath(s, BrowserPurpose::kExportXrayVolume, a);
}

Status exportSize(AppState& s, const ActionArgs& a) {  // W H: the 3D view's export size (0 0: as shown)
  int32_t w = 0, h = 0;
  if (!parseNumber(a.words[0], w) || !parseNumber(a.words[1], h) || w < 0 || h < 0 || w > 8192 || h > 8192) {
    return badValues("export-size takes a width and a height in pixels, 0 to 8192");
  }
  s.export_width = w;
  s.export_height = h;
  return Ok{};
}

// ---- Edit ----
void measureClear(AppState& s) { clearMeasure(s); }

Status measureAt(AppState& s, const ActionArgs& a) {  // I J K: pick a voxel as a click does
  int32_t v[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    if (!parseNumber(a.words[size_t(i)], v[i])) return badValues("measure takes I J K, a voxel index");
  }
  if (!s.model.inBounds(v[0], v[1], v[2])) return badValues("measure: voxel outside the model's grid");
  addMeasurePick(s, glm::ivec3(v[0], v[1], v[2]));
  return Ok{};
}

// ---- Model ----
void voxelizeDialog(AppState& s) { s.voxelize.open_requested = true; }

Status voxelizeAt(AppState& s, const ActionArgs& a) {  // R [MODE], as the dialog's Voxelize button
  VoxelizeParams p = s.voxelize.params;
  if (!parseNumber(a.words[0], p.resolution) || p.resolution < 1) {
    return badValues("resolution must be a positive integer, found '" + a.words[0] + "'");
  }
  p.voxel_size = 0.0;
  if (a.words.size() > 1) {
    auto mode = parseFillMode(a.words[1]);
    if (!mode) return badValues("unknown mode '" + a.words[1] + "' (" + fillModeNames() + ")");
    p.mode = *mode;
  }
  s.voxelize.params = p;
  startVoxelize(s, p);
  return Ok{};
}

void cancelAll(AppState& s) {
  cancelJobs(s);
  cancelThickness(s);
  cancelPrint(s);
  cancelSkinLayers(s);
  cancelVolumeExport(s);
  s.parts_job.cancel();
  cancelInterference(s);
  s.clearance_job.abandon();  // the distance transform has no progress to stop at: its result is dropped
}

// ---- View ----
void fit(AppState& s) { s.view.fit_pending = true; }
void viewIso(AppState& s) { standardView(s, render::StandardView::kIso); }
void viewPosX(AppState& s) { standardView(s, render::StandardView::kPosX); }
void viewNegX(AppState& s) { standardView(s, render::StandardView::kNegX); }
void viewPosY(AppState& s) { standardView(s, render::StandardView::kPosY); }
void viewNegY(AppState& s) { standardView(s, render::StandardView::kNegY); }
void viewPosZ(AppState& s) { standardView(s, render::StandardView::kPosZ); }
void viewNegZ(AppState& s) { standardView(s, render::StandardView::kNegZ); }

Status viewAngles(AppState& s, const ActionArgs& a) {  // YAW PITCH in degrees; refits the model
  double yaw = 0.0, pitch = 0.0;
  if (!parseNumber(a.words[0], yaw) || !parseNumber(a.words[1], pitch))
    return badValues("view YAW PITCH takes degrees");
  s.view.camera.yaw_deg = yaw;
  s.view.camera.pitch_deg = std::clamp(pitch, -90.0, 90.0);
  s.view.fit_pending = true;
  return Ok{};
}

void zoomIn(AppState& s) { s.view.camera.zoom(1.25); }
void zoomOut(AppState& s) { s.view.camera.zoom(1.0 / 1.25); }
Status zoomBy(AppState& s, const ActionArgs& a) {  // FACTOR: > 1 zooms in
  double f = 0.0;
  if (!parseNumber(a.words[0], f) || !(f > 0.0)) return badValues("zoom takes a positive factor");
  s.view.camera.zoom(f);
  return Ok{};
}

void toggleLit(AppState& s) { s.view.lit = !s.view.lit; }
bool isLit(const AppState& s) { return s.view.lit; }
void toggleRound(AppState& s) { s.view.round_points = !s.view.round_points; }
bool isRound(const AppState& s) { return s.view.round_points; }
void toggleLod(AppState& s) { s.view.lod = !s.view.lod; }
bool isLod(const AppState& s) { return s.view.lod; }
void toggleCut(AppState& s) { s.view.cut_away = !s.view.cut_away; }
bool isCut(const AppState& s) { return s.view.cut_away; }
void toggleDisputed(AppState& s) { s.view.show_disputed = !s.view.show_disputed; }
bool isDisputed(const AppState& s) { return s.view.show_disputed; }

void panelModel(AppState& s) { showPanel(s, Panel::kModel); }
bool onModel(const AppState& s) { return s.panel == Panel::kModel; }
void panelSection(AppState& s) { showPanel(s, Panel::kSection); }
bool onSection(const AppState& s) { return s.panel == Panel::kSection; }
void panelSkin(AppState& s) { showPanel(s, Panel::kSkin); }
bool onSkin(const AppState& s) { return s.panel == Panel::kSkin; }
void panelXray(AppState& s) { showPanel(s, Panel::kXray); }
bool onXray(const AppState& s) { return s.panel == Panel::kXray; }
void panelMass(AppState& s) { showPanel(s, Panel::kMass); }
bool onMass(const AppState& s) { return s.panel == Panel::kMass; }
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

// Row N (from 1) of a list of `count` rows, N the action's word; the messages name the action (`what`), its rows
// (`row`) and why the list is empty (`none`).
Result<size_t> listRow(const ActionArgs& a, size_t count, const char* what, const char* row, const char* none) {
  if (count == 0) return badValues(std::string(what) + ": " + none);
  size_t n = 0;
  if (!parseNumber(a.words[0], n) || n < 1 || n > count) {
    return badValues(std::string(what) + " takes " + row + " number in the Thickness panel's list, 1 to " +
                     std::to_string(count));
  }
  return n - 1;
}

}  // namespace

Status thinRegionAt(AppState& s, const ActionArgs& a) {
  if (currentThickness(s) && !currentThinWalls(s)) {
    return badValues("thin-region: the walls under the minimum wall are still being found");
  }
  const Walls* thin = currentThinWalls(s);
  const auto i = listRow(a, thin ? thin->regions.size() : 0, "thin-region", "a region's",
                         "no wall is thinner than the minimum wall");
  if (!i) return i.error();
  const ThinWallRegion& g = thin->regions[*i];
  showThicknessPlace(s, g.bbox_min_ijk, g.bbox_max_ijk);
  select(s.thickness_ui, currentThickness(s)->id).selected_region = int32_t(*i);
  return Ok{};
}

Status hotSpotAt(AppState& s, const ActionArgs& a) {
  const ThicknessResult* r = currentThickness(s);
  const auto i = listRow(a, r ? r->hot_spots.size() : 0, "hot-spot", "a hot spot's", "the thickness has no hot spot");
  if (!i) return i.error();
  const HotSpot& spot = r->hot_spots[*i];
  const auto reach = int32_t(std::ceil(spot.radius / s.model.voxelSize()));  // its inscribed ball
  showThicknessPlace(s, spot.voxel - reach, spot.voxel + reach);
  select(s.thickness_ui, r->id).selected_spot = int32_t(*i);
  return Ok{};
}

// ---- Section ----
void sectionPrev(AppState& s) { stepSection(s, -s.section.step); }
void sectionNext(AppState& s) { stepSection(s, s.section.step); }
void sectionPlay(AppState& s) {
  s.section.playing = !s.section.playing;
  showPanel(s, Panel::kSection);
}
bool isPlaying(const AppState& s) { return s.section.playing; }

Status sectionAt(AppState& s, const ActionArgs& a) {  // AXIS INDEX: the slider's place, with the cut-away shown
  auto axis = parseAxis(a.words[0]);
  int32_t index = 0;
  if (!axis) return badValues("unknown axis '" + a.words[0] + "' (x, y or z)");
  if (!parseNumber(a.words[1], index)) return badValues("section needs an integer index");
  const int32_t n = axisLength(s, *axis);
  if (index < 0 || index >= n) {
    return badValues("section index " + std::to_string(index) + " is outside 0.." + std::to_string(n - 1));
  }
  s.section.axis = *axis;
  s.section.index = index;
  s.section.oblique = false;
  s.view.cut_away = true;
  showPanel(s, Panel::kSection);
  return Ok{};
}

Status sectionPlane(AppState& s, const ActionArgs& a) {
  glm::dvec3 n(0.0);
  for (int k = 0; k < 3; ++k) {
    if (!parseFileNumber(a.words[size_t(k)], n[k])) return badValues("section-plane takes NX NY NZ [OFFSET]");
  }
  if (n == glm::dvec3(0.0)) return badValues("section-plane: the normal must not be zero");
  double offset = 0.0;
  if (a.words.size() == 4 && !parseFileNumber(a.words[3], offset)) {
    return badValues("section-plane: '" + a.words[3] + "' is not an offset in model units");
  }
  s.section.normal = n;
  s.section.offset = offset;
  s.section.oblique = true;
  showPanel(s, Panel::kSection);
  return Ok{};
}

// ---- Skin ----
void peelOne(AppState& s) { peelTo(s, peeled(s) + 1); }
void peelN(AppState& s) { peelTo(s, peeled(s) + s.skin.peel_count); }
Status peelCount(AppState& s, const ActionArgs& a) {  // N: peel N more layers
  int32_t n = 0;
  if (!parseNumber(a.words[0], n) || n < 0) return badValues("peel takes a layer count, found '" + a.words[0] + "'");
  showPanel(s, Panel::kSkin);
  peelTo(s, peeled(s) + n);
  return Ok{};
}
void peelBack(AppState& s) { peelTo(s, peeled(s) - 1); }
// Every layer but the last; peelTo clamps, and a queued peel resolves once the layers are known.
void peelCore(AppState& s) { peelTo(s, std::numeric_limits<int32_t>::max()); }
void peelReset(AppState& s) { peelTo(s, 0); }
// The Skin panel's distance (one voxel when none was chosen), or D model units: the round skin removal.
void peelDistanceN(AppState& s) {
  const double d = s.skin.peel_distance > 0.0f ? double(s.skin.peel_distance) : s.model.voxelSize();
  if (Status st = peelDistance(s, d); !st) reportError(s, st.error().message);
}
Status peelDistanceAt(AppState& s, const ActionArgs& a) {
  double d = 0.0;
  if (!parseNumber(a.words[0], d) || !(d >= 0.0))
    return badValues("peel-distance takes a distance >= 0 in model units");
  s.skin.peel_distance = float(d);
  showPanel(s, Panel::kSkin);
  return peelDistance(s, d);
}

// ---- X-ray ----
Status xrayAlong(AppState& s, const ActionArgs& a) {  // AXIS MODE, as the X-ray panel's buttons
  auto axis = parseAxis(a.words[0]);
  auto mode = parseXrayMode(a.words[1]);
  if (!axis) return badValues("unknown axis '" + a.words[0] + "' (x, y or z)");
  if (!mode) return badValues("unknown X-ray mode '" + a.words[1] + "' (min, max or total)");
  s.xray.params = XrayParams{*axis, *mode};
  showPanel(s, Panel::kXray);
  return Ok{};
}

// ---- Help and dialogs ----
void controls(AppState& s) { s.show_controls = true; }
void about(AppState& s) { s.show_about = true; }
void closeDialogs(AppState& s) { s.close_dialogs = true; }

}  // namespace vox::app::actions
