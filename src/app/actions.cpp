#include "app/actions.h"

#include <algorithm>
#include <cassert>
#include <limits>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/operations.h"

namespace vox::app {
namespace {

constexpr int kCtrl = GLFW_MOD_CONTROL;
constexpr int kShift = GLFW_MOD_SHIFT;

bool hasModel(const AppState& s) { return s.doc.model.has_value() && !modelBusy(s); }
bool hasMesh(const AppState& s) { return s.doc.mesh != nullptr && !s.load_job.active(); }
bool hasSection(const AppState& s) { return !s.model.empty(); }
// An X-ray export needs the X-ray computed (the X-ray panel computes it); until then the menu item is off.
bool hasXray(const AppState& s) { return currentXray(s) != nullptr; }

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
bool canPeel(const AppState& s) {
  const int32_t layers = peelLayersAvailable(s);
  return hasModel(s) && (layers < 0 || peeled(s) < layers - 1);
}
bool canPeelBack(const AppState& s) { return hasModel(s) && peeled(s) > 0; }

const Action kActions[] = {
    {ActionId::kOpen,
     "File",
     "Open...",
     {GLFW_KEY_O, kCtrl},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kOpen); },
     nullptr,
     nullptr},
    {ActionId::kSave, "File", "Save", {GLFW_KEY_S, kCtrl}, [](AppState& s) { saveOrAsk(s); }, hasModel, nullptr},
    {ActionId::kSaveAs,
     "File",
     "Save As...",
     {GLFW_KEY_S, kCtrl | kShift},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kSaveModel); },
     hasModel,
     nullptr},
    {ActionId::kExportBinvox,
     "File",
     "Export binvox...",
     {},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kExportBinvox); },
     hasModel,
     nullptr},
    {ActionId::kExportViewPng,
     "File",
     "Export 3D view PNG...",
     {GLFW_KEY_E, kCtrl},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kExportViewPng); },
     hasModel,
     nullptr},
    {ActionId::kExportSectionPng,
     "File",
     "Export section PNG...",
     {},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kExportSectionPng); },
     hasSection,
     nullptr},
    {ActionId::kExportXrayPng,
     "File",
     "Export X-ray PNG...",
     {},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kExportXrayPng); },
     hasXray,
     nullptr},
    {ActionId::kExportXrayCsv,
     "File",
     "Export X-ray CSV...",
     {},
     [](AppState& s) { openBrowser(s, BrowserPurpose::kExportXrayCsv); },
     hasXray,
     nullptr},
    {ActionId::kQuit, "File", "Quit", {GLFW_KEY_Q, kCtrl}, requestQuit, nullptr, nullptr},

    {ActionId::kUndo, "Edit", "Undo", {GLFW_KEY_Z, kCtrl}, undo, canUndo, nullptr},
    {ActionId::kRedo, "Edit", "Redo", {GLFW_KEY_Y, kCtrl}, redo, canRedo, nullptr},

    {ActionId::kVoxelize,
     "Model",
     "Voxelize...",
     {GLFW_KEY_R, kCtrl},
     [](AppState& s) { s.voxelize.open_requested = true; },
     hasMesh,
     nullptr},
    {ActionId::kCancelJob,
     "Model",
     "Cancel voxelizing / loading",
     {GLFW_KEY_ESCAPE, 0},
     cancelJobs,
     modelBusy,
     nullptr},

    {ActionId::kViewFit,
     "View",
     "Fit model",
     {GLFW_KEY_F, 0},
     [](AppState& s) { s.view.fit_pending = true; },
     nullptr,
     nullptr},
    {ActionId::kViewIso,
     "View",
     "Isometric",
     {GLFW_KEY_0, 0},
     [](AppState& s) { standardView(s, render::StandardView::kIso); },
     nullptr,
     nullptr},
    {ActionId::kViewPosX,
     "View",
     "From +X",
     {GLFW_KEY_1, 0},
     [](AppState& s) { standardView(s, render::StandardView::kPosX); },
     nullptr,
     nullptr},
    {ActionId::kViewNegX,
     "View",
     "From -X",
     {GLFW_KEY_1, kShift},
     [](AppState& s) { standardView(s, render::StandardView::kNegX); },
     nullptr,
     nullptr},
    {ActionId::kViewPosY,
     "View",
     "From +Y",
     {GLFW_KEY_2, 0},
     [](AppState& s) { standardView(s, render::StandardView::kPosY); },
     nullptr,
     nullptr},
    {ActionId::kViewNegY,
     "View",
     "From -Y",
     {GLFW_KEY_2, kShift},
     [](AppState& s) { standardView(s, render::StandardView::kNegY); },
     nullptr,
     nullptr},
    {ActionId::kViewPosZ,
     "View",
     "From +Z",
     {GLFW_KEY_3, 0},
     [](AppState& s) { standardView(s, render::StandardView::kPosZ); },
     nullptr,
     nullptr},
    {ActionId::kViewNegZ,
     "View",
     "From -Z",
     {GLFW_KEY_3, kShift},
     [](AppState& s) { standardView(s, render::StandardView::kNegZ); },
     nullptr,
     nullptr},
    {ActionId::kViewLit,
     "View",
     "Lit shading (off: thesis table)",
     {GLFW_KEY_L, 0},
     [](AppState& s) { s.view.lit = !s.view.lit; },
     nullptr,
     [](const AppState& s) { return s.view.lit; }},
    {ActionId::kViewRound,
     "View",
     "Round points (smoothing)",
     {},
     [](AppState& s) { s.view.round_points = !s.view.round_points; },
     nullptr,
     [](const AppState& s) { return s.view.round_points; }},
    {ActionId::kViewLod,
     "View",
     "Coarser points while moving",
     {},
     [](AppState& s) { s.view.lod = !s.view.lod; },
     nullptr,
     [](const AppState& s) { return s.view.lod; }},
    {ActionId::kViewDisputed,
     "View",
     "Show disputed voxels (vote mode)",
     {GLFW_KEY_D, 0},
     [](AppState& s) { s.view.show_disputed = !s.view.show_disputed; },
     [](const AppState& s) { return s.doc.model && s.doc.model->origin && s.doc.model->origin->disputed != nullptr; },
     [](const AppState& s) { return s.view.show_disputed; }},

    {ActionId::kPanelModel,
     "View",
     "Model panel",
     {GLFW_KEY_1, kCtrl},
     [](AppState& s) { showPanel(s, Panel::kModel); },
     nullptr,
     [](const AppState& s) { return s.panel == Panel::kModel; }},
    {ActionId::kPanelSection,
     "View",
     "Section panel",
     {GLFW_KEY_2, kCtrl},
     [](AppState& s) { showPanel(s, Panel::kSection); },
     nullptr,
     [](const AppState& s) { return s.panel == Panel::kSection; }},
    {ActionId::kPanelSkin,
     "View",
     "Skin removal panel",
     {GLFW_KEY_3, kCtrl},
     [](AppState& s) { showPanel(s, Panel::kSkin); },
     nullptr,
     [](const AppState& s) { return s.panel == Panel::kSkin; }},
    {ActionId::kPanelXray,
     "View",
     "X-ray panel",
     {GLFW_KEY_4, kCtrl},
     [](AppState& s) { showPanel(s, Panel::kXray); },
     nullptr,
     [](const AppState& s) { return s.panel == Panel::kXray; }},
    {ActionId::kPanelMass,
     "View",
     "Mass properties panel",
     {GLFW_KEY_5, kCtrl},
     [](AppState& s) { showPanel(s, Panel::kMass); },
     nullptr,
     [](const AppState& s) { return s.panel == Panel::kMass; }},

    {ActionId::kSectionPrev,
     "Section",
     "Previous section",
     {GLFW_KEY_PAGE_DOWN, 0},
     [](AppState& s) { stepSection(s, -s.section.step); },
     hasSection,
     nullptr},
    {ActionId::kSectionNext,
     "Section",
     "Next section",
     {GLFW_KEY_PAGE_UP, 0},
     [](AppState& s) { stepSection(s, s.section.step); },
     hasSection,
     nullptr},
    {ActionId::kSectionPlay,
     "Section",
     "Play / pause sections",
     {GLFW_KEY_SPACE, 0},
     [](AppState& s) {
       s.section.playing = !s.section.playing;
       showPanel(s, Panel::kSection);
     },
     hasSection,
     [](const AppState& s) { return s.section.playing; }},

    {ActionId::kPeelOne,
     "Skin",
     "Peel one layer",
     {GLFW_KEY_P, 0},
     [](AppState& s) { peelTo(s, peeled(s) + 1); },
     canPeel,
     nullptr},
    {ActionId::kPeelN,
     "Skin",
     "Peel N layers",
     {},
     [](AppState& s) { peelTo(s, peeled(s) + s.skin.peel_count); },
     canPeel,
     nullptr},
    {ActionId::kPeelBack,
     "Skin",
     "Back one layer",
     {GLFW_KEY_P, kShift},
     [](AppState& s) { peelTo(s, peeled(s) - 1); },
     canPeelBack,
     nullptr},
    {ActionId::kPeelCore,
     "Skin",
     "Peel to the core",
     {GLFW_KEY_C, 0},
     [](AppState& s) {
       // Every layer but the last; peelTo clamps, and a queued peel resolves once the layers are known.
       peelTo(s, std::numeric_limits<int32_t>::max());
     },
     canPeel,
     nullptr},
    {ActionId::kPeelReset, "Skin", "Reset skin", {}, [](AppState& s) { peelTo(s, 0); }, canPeelBack, nullptr},

    {ActionId::kControls,
     "Help",
     "Mouse and keyboard",
     {GLFW_KEY_F1, 0},
     [](AppState& s) { s.show_controls = true; },
     nullptr,
     nullptr},
    {ActionId::kAbout, "Help", "About voxmod", {}, [](AppState& s) { s.show_about = true; }, nullptr, nullptr},
};

}  // namespace

std::span<const Action> actionTable() { return kActions; }

const Action& action(ActionId id) {
  for (const Action& a : kActions) {
    if (a.id == id) return a;
  }
  assert(false && "every ActionId has a table entry");
  return kActions[0];
}

bool actionEnabled(const AppState& state, const Action& a) { return !a.enabled || a.enabled(state); }

bool dispatch(AppState& state, ActionId id) {
  const Action& a = action(id);
  if (!actionEnabled(state, a)) return false;
  a.run(state);
  state.redraw_frames = std::max(state.redraw_frames, 2);
  return true;
}

std::string shortcutText(const Shortcut& s) {
  if (s.key == 0) return {};
  std::string t;
  if (s.mods & GLFW_MOD_CONTROL) t += "Ctrl+";
  if (s.mods & GLFW_MOD_SHIFT) t += "Shift+";
  switch (s.key) {
    case GLFW_KEY_ESCAPE:
      return t + "Esc";
    case GLFW_KEY_F1:
      return t + "F1";
    case GLFW_KEY_SPACE:
      return t + "Space";
    case GLFW_KEY_PAGE_UP:
      return t + "PgUp";
    case GLFW_KEY_PAGE_DOWN:
      return t + "PgDn";
    default:
      break;
  }
  if ((s.key >= GLFW_KEY_A && s.key <= GLFW_KEY_Z) || (s.key >= GLFW_KEY_0 && s.key <= GLFW_KEY_9)) {
    return t + char(s.key);  // GLFW key codes of letters and digits are their ASCII codes
  }
  return t + "?";
}

}  // namespace vox::app
