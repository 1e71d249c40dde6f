#include "app/action_functions.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>

#include "app/document.h"
#include "app/glossary.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/parts.h"
#include "app/print.h"
#include "vox/core/text.h"
#include "vox/core/units.h"

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
void showPanel(AppState& s, Panel p) {
  s.panel = p;
  s.panel_change_requested = true;
}

namespace {

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

// ---- Edit ----
void measureClear(AppState& s) { clearMeasure(s.measure); }

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

Status modelUnitsAt(AppState& s, const ActionArgs& a) {
  const std::string& u = a.words[0];
  if (std::find(kLengthUnits.begin(), kLengthUnits.end(), u) == kLengthUnits.end()) {
    std::string known;
    for (std::string_view k : kLengthUnits) known += (known.empty() ? "" : ", ") + std::string(k);
    return badValues("model-units takes one of " + known + ", found '" + u + "'");
  }
  setModelUnits(s, u);
  return Ok{};
}

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
void toggleOrtho(AppState& s) {
  render::Projection& p = s.view.camera.projection;
  p = p == render::Projection::kOrthographic ? render::Projection::kPerspective : render::Projection::kOrthographic;
}
bool isOrthographic(const AppState& s) { return s.view.camera.projection == render::Projection::kOrthographic; }

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
  if (*axis != s.section.axis) sectionWhole(s);  // another picture: shown whole
  s.section.axis = *axis;
  s.section.index = index;
  s.section.oblique = false;
  s.view.cut_away = true;
  showPanel(s, Panel::kSection);
  return Ok{};
}

Status sectionZoom(AppState& s, const ActionArgs& a) {
  double zoom = 0.0;
  if (!parseFileNumber(a.words[0], zoom) || !(zoom >= 1.0 && zoom <= kMaxSectionZoom)) {
    return badValues("section-zoom takes a zoom from 1 (the whole section) to " + std::to_string(int(kMaxSectionZoom)) +
                     ", then the voxel U V to zoom about");
  }
  if (a.words.size() == 2) return badValues("section-zoom takes Z, or Z U V (the voxel along right and up)");
  // default: about the voxel in the middle now
  const double w = std::max(axisLength(s, imageRightAxis(s.section.axis)), 1);
  const double h = std::max(axisLength(s, imageUpAxis(s.section.axis)), 1);
  glm::dvec2 uv(s.section.centre.x * w - 0.5, s.section.centre.y * h - 0.5);
  if (a.words.size() == 3 && (!parseFileNumber(a.words[1], uv.x) || !parseFileNumber(a.words[2], uv.y))) {
    return badValues("section-zoom: U and V are voxels along the picture's right and up axes");
  }
  zoomSection(s, zoom, uv);
  // The panels whose picture is the axis section (the Parts and Print panels show it, the Thickness panel coloured by
  // thickness) keep it; another panel gives way to the Section panel's.
  const Panel p = s.panel;
  if (p != Panel::kSection && p != Panel::kThickness && p != Panel::kParts && p != Panel::kPrint) {
    showPanel(s, Panel::kSection);
  }
  return Ok{};
}

void sectionWhole(AppState& s) {
  s.section.zoom = 1.0;
  s.section.centre = glm::dvec2(0.5);
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
void controls(AppState& s) { s.help.show_controls = true; }
void about(AppState& s) { s.help.show_about = true; }
void terms(AppState& s) {
  s.help.show_terms = true;
  s.help.term.clear();
}
Status termsAt(AppState& s, const ActionArgs& a) {
  std::string words;  // "suspect voxels" as well as "suspect-voxels"
  for (const std::string& w : a.words) words += (words.empty() ? "" : " ") + w;
  const Term* t = findTerm(words);
  if (!t) return badValues("no term '" + words + "' (known: " + termKeys() + ")");
  s.help.show_terms = true;
  s.help.term = t->key;
  return Ok{};
}
void closeDialogs(AppState& s) { s.close_dialogs = true; }

}  // namespace vox::app::actions
