#include "app/actions.h"

#include <algorithm>
#include <cassert>
#include <functional>
#include <new>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/action_functions.h"
#include "app/operations.h"
#include "app/parts.h"

namespace vox::app {
namespace {

using namespace actions;  // NOLINT(google-build-using-namespace): the table names the functions it runs

constexpr int kCtrl = GLFW_MOD_CONTROL;
constexpr int kShift = GLFW_MOD_SHIFT;
constexpr Shortcut kNone{};

// clang-format off
const Action kActions[] = {
  // id                       name               menu       label                                 shortcut                   values  run            run_with           enabled      checked
  {ActionId::kOpen,           "open",            "File",    "Open...",                            {GLFW_KEY_O, kCtrl},         1, -1, open,          openPath,          nullptr,     nullptr},
  {ActionId::kSave,           "save",            "File",    "Save",                               {GLFW_KEY_S, kCtrl},         1, -1, save,          savePath,          hasModel,    nullptr},
  {ActionId::kSaveAs,         "save-as",         "File",    "Save As...",                         {GLFW_KEY_S, kCtrl | kShift}, 1, -1, saveAs,       savePath,          hasModel,    nullptr},
  {ActionId::kSaveParts,      "save-parts",      "File",    "Save each part to a folder...",      kNone,                       1, -1, savePartsDialog, savePartsPath,   hasPartsNow, nullptr},
  {ActionId::kRecoverAutosave, "recover-autosave", "File", "Recover unsaved work",             kNone,                       0, 0,  recoverAutosave, nullptr,         hasOrphanAutosave, nullptr},
  {ActionId::kDiscardAutosave, "discard-autosave", nullptr, "Discard the unsaved work found",  kNone,                       0, 0,  discardAutosave, nullptr,         hasOrphanAutosave, nullptr},
  {ActionId::kExportBinvox,   "export-binvox",   "File",    "Export binvox...",                   kNone,                       1, -1, exportBinvox,  exportBinvoxPath,  hasModel,    nullptr},
  {ActionId::kExportSurface,  "export-surface",  "File",    "Export surface mesh (STL, PLY, OBJ, 3MF)...", kNone,              1, -1, exportSurface, exportSurfacePath, hasModel,    nullptr},
  {ActionId::kExportSmoothSurface, "export-smooth-surface", "File", "Export smooth surface mesh...", kNone,            1, -1, exportSmoothSurface, exportSmoothSurfacePath, hasModel, nullptr},
  {ActionId::kExportViewPng,  "export-view",     "File",    "Export 3D view PNG...",              {GLFW_KEY_E, kCtrl},         1, -1, exportView,    exportViewPath,    hasModel,    nullptr},
  {ActionId::kExportSectionPng, "export-section", "File",   "Export section PNG...",              kNone,                       1, -1, exportSection, exportSectionPath, hasSection,  nullptr},
  {ActionId::kExportXrayPng,  "export-xray",     "File",    "Export X-ray PNG...",                kNone,                       1, -1, exportXray,    exportXrayPath,    hasXray,     nullptr},
  {ActionId::kExportXrayCsv,  "export-csv",      "File",    "Export X-ray CSV...",                kNone,                       1, -1, exportCsv,     exportCsvPath,     hasXray,     nullptr},
  {ActionId::kExportVolume,   "export-volume",   "File",    "Export volume (.vti .vdb .nrrd .vox)...", kNone,                  1, -1, exportVolume,  exportVolumePath,  hasModel,    nullptr},
  {ActionId::kExportThickness, "export-thickness", "File",  "Export thickness volume (.vti .vdb .nrrd)...", kNone,              1, -1, exportThickness, exportThicknessPath, hasThickness, nullptr},
  {ActionId::kExportDepth,    "export-depth",    "File",    "Export depth volume (.vti .vdb .nrrd)...", kNone,                  1, -1, exportDepth,   exportDepthPath,   hasDepth,    nullptr},
  {ActionId::kExportXrayVolume, "export-xray-volume", "File", "Export X-ray volume (.vti .vdb .nrrd)...", kNone,                 1, -1, exportXrayVolume, exportXrayVolumePath, hasXray, nullptr},
  {ActionId::kExportReport,   "export-report",   "File",    "Export report (HTML)...",            kNone,                       1, -1, exportReport,  exportReportPath,  hasModel,    nullptr},
  {ActionId::kExportSize,     "export-size",     nullptr,   "3D view export size",                kNone,                       2, 2,  nullptr,       exportSize,        nullptr,     nullptr},
  {ActionId::kQuit,           "quit",            "File",    "Quit",                               {GLFW_KEY_Q, kCtrl},         0, 0,  requestQuit,   nullptr,           nullptr,     nullptr},

  {ActionId::kUndo,           "undo",            "Edit",    "Undo",                               {GLFW_KEY_Z, kCtrl},         0, 0,  undo,          nullptr,           canUndo,     nullptr},
  {ActionId::kRedo,           "redo",            "Edit",    "Redo",                               {GLFW_KEY_Y, kCtrl},         0, 0,  redo,          nullptr,           canRedo,     nullptr},
  {ActionId::kMeasureClear,   "measure-clear",   "Edit",    "Clear measurement",                  kNone,                       0, 0,  measureClear,  nullptr,           hasMeasure,  nullptr},
  {ActionId::kMeasure,        "measure",         nullptr,   "Pick a voxel to measure",            kNone,                       3, 3,  nullptr,       measureAt,         hasSection,  nullptr},

  {ActionId::kVoxelize,       "voxelize",        "Model",   "Voxelize...",                        {GLFW_KEY_R, kCtrl},         1, 2,  voxelizeDialog, voxelizeAt,       hasMesh,     nullptr},
  {ActionId::kModelUnits,     "model-units",     nullptr,   "Model units",                        kNone,                       1, 1,  nullptr,       modelUnitsAt,      hasModel,    nullptr},
  {ActionId::kCancelJob,      "cancel",          "Model",   "Cancel voxelizing / loading / thickness / parts / export", {GLFW_KEY_ESCAPE, 0}, 0, 0, cancelAll,   nullptr,           canCancel,   nullptr},

  {ActionId::kViewFit,        "fit",             "View",    "Fit model",                          {GLFW_KEY_F, 0},             0, 0,  fit,           nullptr,           nullptr,     nullptr},
  {ActionId::kViewIso,        "view-iso",        "View",    "Isometric",                          {GLFW_KEY_0, 0},             0, 0,  viewIso,       nullptr,           nullptr,     nullptr},
  {ActionId::kViewPosX,       "view-pos-x",      "View",    "From +X",                            {GLFW_KEY_1, 0},             0, 0,  viewPosX,      nullptr,           nullptr,     nullptr},
  {ActionId::kViewNegX,       "view-neg-x",      "View",    "From -X",                            {GLFW_KEY_1, kShift},        0, 0,  viewNegX,      nullptr,           nullptr,     nullptr},
  {ActionId::kViewPosY,       "view-pos-y",      "View",    "From +Y",                            {GLFW_KEY_2, 0},             0, 0,  viewPosY,      nullptr,           nullptr,     nullptr},
  {ActionId::kViewNegY,       "view-neg-y",      "View",    "From -Y",                            {GLFW_KEY_2, kShift},        0, 0,  viewNegY,      nullptr,           nullptr,     nullptr},
  {ActionId::kViewPosZ,       "view-pos-z",      "View",    "From +Z",                            {GLFW_KEY_3, 0},             0, 0,  viewPosZ,      nullptr,           nullptr,     nullptr},
  {ActionId::kViewNegZ,       "view-neg-z",      "View",    "From -Z",                            {GLFW_KEY_3, kShift},        0, 0,  viewNegZ,      nullptr,           nullptr,     nullptr},
  {ActionId::kViewOrtho,      "ortho",           "View",    "Orthographic projection",            {GLFW_KEY_5, 0},             0, 0,  toggleOrtho,   nullptr,           nullptr,     isOrthographic},
  {ActionId::kViewAngles,     "view",            nullptr,   "Camera angles",                      kNone,                       2, 2,  nullptr,       viewAngles,        nullptr,     nullptr},
  {ActionId::kZoomIn,         "zoom-in",         "View",    "Zoom in",                            {GLFW_KEY_EQUAL, 0},         0, 0,  zoomIn,        nullptr,           nullptr,     nullptr},
  {ActionId::kZoomOut,        "zoom-out",        "View",    "Zoom out",                           {GLFW_KEY_MINUS, 0},         0, 0,  zoomOut,       nullptr,           nullptr,     nullptr},
  {ActionId::kZoom,           "zoom",            nullptr,   "Zoom by a factor",                   kNone,                       1, 1,  nullptr,       zoomBy,            nullptr,     nullptr},
  {ActionId::kViewLit,        "lit",             "View",    "Lit shading (off: thesis table)",    {GLFW_KEY_L, 0},             0, 0,  toggleLit,     nullptr,           nullptr,     isLit},
  {ActionId::kViewRound,      "round",           "View",    "Round points (smoothing)",           kNone,                       0, 0,  toggleRound,   nullptr,           nullptr,     isRound},
  {ActionId::kViewLod,        "lod",             "View",    "Coarser points while moving",        kNone,                       0, 0,  toggleLod,     nullptr,           nullptr,     isLod},
  {ActionId::kViewCut,        "cut",             "View",    "Cut away at the section",            kNone,                       0, 0,  toggleCut,     nullptr,           nullptr,     isCut},
  {ActionId::kViewDisputed,   "disputed",        "View",    "Show disputed voxels (vote mode)",   {GLFW_KEY_D, 0},             0, 0,  toggleDisputed, nullptr,          hasDisputed, isDisputed},

  {ActionId::kPanelModel,     "panel-model",     "View",    "Model panel",                        {GLFW_KEY_1, kCtrl},         0, 0,  panelModel,    nullptr,           nullptr,     onModel},
  {ActionId::kPanelSection,   "panel-section",   "View",    "Section panel",                      {GLFW_KEY_2, kCtrl},         0, 0,  panelSection,  nullptr,           nullptr,     onSection},
  {ActionId::kPanelSkin,      "panel-skin",      "View",    "Skin removal panel",                 {GLFW_KEY_3, kCtrl},         0, 0,  panelSkin,     nullptr,           nullptr,     onSkin},
  {ActionId::kPanelXray,      "panel-xray",      "View",    "X-ray panel",                        {GLFW_KEY_4, kCtrl},         0, 0,  panelXray,     nullptr,           nullptr,     onXray},
  {ActionId::kPanelMass,      "panel-mass",      "View",    "Mass properties panel",              {GLFW_KEY_5, kCtrl},         0, 0,  panelMass,     nullptr,           nullptr,     onMass},
  {ActionId::kPanelThickness, "panel-thickness", "View",    "Thickness panel",                    {GLFW_KEY_6, kCtrl},         0, 0,  panelThickness, nullptr,          nullptr,     onThickness},
  {ActionId::kPanelParts,     "panel-parts",     "View",    "Parts panel",                        {GLFW_KEY_7, kCtrl},         0, 0,  panelParts,    nullptr,           nullptr,     onParts},
  {ActionId::kPanelPrint,     "panel-print",     "View",    "Print panel",                        {GLFW_KEY_8, kCtrl},         0, 0,  panelPrint,    nullptr,           nullptr,     onPrint},
  {ActionId::kMinWall,        "min-wall",        nullptr,   "Minimum wall (model units)",         kNone,                       1, 1,  nullptr,       minWallAt,         hasSection,  nullptr},
  {ActionId::kMinArea,        "min-area",        nullptr,   "Smallest wall listed (model units^2)", kNone,                     1, 1,  nullptr,       minAreaAt,         hasSection,  nullptr},
  {ActionId::kThicknessMethod, "thickness-method", nullptr, "Thickness shown: sphere or ray",    kNone,                       1, 1,  nullptr,       thicknessMethodAt, hasSection,  nullptr},
  {ActionId::kThinRegion,     "thin-region",     nullptr,   "Show a thin-wall region",            kNone,                       1, 1,  nullptr,       thinRegionAt,      hasThickness, nullptr},
  {ActionId::kHotSpot,        "hot-spot",        nullptr,   "Show a hot spot",                    kNone,                       1, 1,  nullptr,       hotSpotAt,         hasThickness, nullptr},

  {ActionId::kComputeThickness, "compute-thickness", nullptr, "Compute thickness",              kNone,                       0, 0,  retryThickness, nullptr,          thicknessCancelled, nullptr},
  {ActionId::kCancelThickness, "cancel-thickness", nullptr,  "Cancel thickness",                 kNone,                       0, 0,  cancelThickness, nullptr,         thicknessComputing, nullptr},
  {ActionId::kCancelRays,     "cancel-rays",     nullptr,   "Cancel casting the rays",            kNone,                       0, 0,  cancelRaysNow, nullptr,           raysComputingNow, nullptr},

  {ActionId::kPrintDirection, "print-direction", nullptr,   "Build direction",                    kNone,                       1, 3,  nullptr,       printDirectionAt,  hasModel,    nullptr},
  {ActionId::kOverhangAngle,  "overhang-angle",  nullptr,   "Overhang angle (degrees)",           kNone,                       1, 1,  nullptr,       overhangAngleAt,   hasModel,    nullptr},
  {ActionId::kPrintOrient,    "print-orient",    nullptr,   "Find the best way up",               kNone,                       0, 0,  printOrient,   nullptr,           hasModel,    nullptr},
  {ActionId::kPrintOrientation, "print-orientation", nullptr, "Print in a direction of the list", kNone,                       1, 1,  nullptr,       printOrientationAt, hasPrint,   nullptr},
  {ActionId::kPrintCavity,    "print-cavity",    nullptr,   "Show a trapped cavity",              kNone,                       1, 1,  nullptr,       printCavityAt,     hasPrint,    nullptr},
  {ActionId::kPrintLayFace,   "print-lay-face",  nullptr,   "Lay a face on the plate",            kNone,                       3, 3,  printLayFaceMode, printLayFaceAt,  hasModel,    nullptr},
  {ActionId::kComputePrint,   "compute-print",   nullptr,   "Check printability",                 kNone,                       0, 0,  computePrint,  nullptr,           printCancelledNow, nullptr},
  {ActionId::kCancelPrint,    "cancel-print",    nullptr,   "Cancel the printability check",      kNone,                       0, 0,  cancelPrintNow, nullptr,          printComputingNow, nullptr},

  {ActionId::kPanelCasting,   "panel-casting",   "View",    "Casting panel",                      {GLFW_KEY_9, kCtrl},         0, 0,  panelCasting,  nullptr,           nullptr,     onCasting},
  {ActionId::kCastingAlloy,   "casting-alloy",   nullptr,   "Alloy poured",                       kNone,                       1, 1,  nullptr,       castingAlloyAt,    hasModel,    nullptr},
  {ActionId::kCastingMould,   "casting-mould",   nullptr,   "Mould",                              kNone,                       1, 1,  nullptr,       castingMouldAt,    hasModel,    nullptr},
  {ActionId::kCastingSuperheat, "casting-superheat", nullptr, "Superheat (K)",                    kNone,                       1, 1,  nullptr,       castingSuperheatAt, hasModel,   nullptr},
  {ActionId::kCastingMouldTemperature, "casting-mould-temperature", nullptr, "Mould temperature (C)", kNone,                  1, 1,  nullptr,       castingMouldTemperatureAt, hasModel, nullptr},
  {ActionId::kCastingFeeder,  "casting-feeder",  nullptr,   "Add a feeder (X Y Z D H)",           kNone,                       5, 5,  nullptr,       castingFeederAt,   hasModel,    nullptr},
  {ActionId::kCastingPlaceFeeder, "casting-place-feeder", nullptr, "Place a feeder by clicking",  kNone,                       3, 3,  castingPlaceFeederMode, castingPlaceFeederAt, hasModel, nullptr},
  {ActionId::kCastingDeleteFeeder, "casting-delete-feeder", nullptr, "Delete a feeder",           kNone,                       1, 1,  nullptr,       castingDeleteFeederAt, hasModel, nullptr},
  {ActionId::kSimulateCasting, "simulate-casting", nullptr,  "Simulate the casting",              kNone,                       0, 0,  simulateCastingNow, nullptr,      canSimulateCasting, nullptr},
  {ActionId::kCancelCasting,  "cancel-casting",  nullptr,   "Cancel the casting simulation",      kNone,                       0, 0,  cancelCastingNow, nullptr,        castingComputingNow, nullptr},
  {ActionId::kCastingField,   "casting-field",   nullptr,   "Colour by: time, niyama or modulus", kNone,                       1, 1,  nullptr,       castingFieldChoice, hasCasting,  nullptr},
  {ActionId::kCastingTime,    "casting-time",    nullptr,   "Freezing front at a time (s)",       kNone,                       1, 1,  nullptr,       castingTimeAt,     hasCasting,  nullptr},
  {ActionId::kCastingPlay,    "casting-play",    nullptr,   "Play / pause the freezing",          kNone,                       0, 0,  castingPlay,   nullptr,           hasCasting,  isCastingPlaying},
  {ActionId::kCastingHotSpot, "casting-hot-spot", nullptr,  "Show a casting hot spot",            kNone,                       1, 1,  nullptr,       castingHotSpotAt,  hasCasting,  nullptr},

  {ActionId::kSectionPrev,    "section-prev",    "Section", "Previous section",                   {GLFW_KEY_PAGE_DOWN, 0},     0, 0,  sectionPrev,   nullptr,           hasSection,  nullptr},
  {ActionId::kSectionNext,    "section-next",    "Section", "Next section",                       {GLFW_KEY_PAGE_UP, 0},       0, 0,  sectionNext,   nullptr,           hasSection,  nullptr},
  {ActionId::kSectionPlay,    "section-play",    "Section", "Play / pause sections",              {GLFW_KEY_SPACE, 0},         0, 0,  sectionPlay,   nullptr,           hasSection,  isPlaying},
  {ActionId::kSectionPlane,   "section-plane",   nullptr,   "Section at an angle",                kNone,                       3, 4,  nullptr,       sectionPlane,      hasSection,  nullptr},
  {ActionId::kSectionPlaneThrough, "section-plane-through", nullptr, "Section through picked voxels", kNone,                 3, 9,  nullptr,       sectionPlaneThrough, hasSection, nullptr},
  {ActionId::kSectionAt,      "section",         nullptr,   "Section at an index",                kNone,                       2, 2,  nullptr,       sectionAt,         hasSection,  nullptr},
  {ActionId::kSectionZoom,    "section-zoom",    "Section", "Whole section (zoom 1)",             kNone,                       1, 3,  sectionWhole,  sectionZoom,       hasSection,  nullptr},

  {ActionId::kPeelOne,        "peel-one",        "Skin",    "Peel one layer",                     {GLFW_KEY_P, 0},             0, 0,  peelOne,       nullptr,           canPeel,     nullptr},
  {ActionId::kPeelN,          "peel",            "Skin",    "Peel N layers",                      kNone,                       1, 1,  peelN,         peelCount,         canPeel,     nullptr},
  {ActionId::kPeelBack,       "peel-back",       "Skin",    "Back one layer",                     {GLFW_KEY_P, kShift},        0, 0,  peelBack,      nullptr,           canPeelBack, nullptr},
  {ActionId::kPeelCore,       "peel-core",       "Skin",    "Peel to the core",                   {GLFW_KEY_C, 0},             0, 0,  peelCore,      nullptr,           canPeel,     nullptr},
  {ActionId::kPeelReset,      "peel-reset",      "Skin",    "Reset skin",                         kNone,                       0, 0,  peelReset,     nullptr,           canPeelBack, nullptr},
  {ActionId::kSkinLayers,     "skin-layers",     nullptr,   "Compute the skin layers",            kNone,                       0, 0,  computeSkinLayers, nullptr,       skinLayersCancelled, nullptr},
  {ActionId::kCancelSkinLayers, "cancel-skin-layers", nullptr, "Cancel the skin layers",          kNone,                       0, 0,  cancelSkinLayers, nullptr,        skinLayersComputing, nullptr},
  {ActionId::kPeelDistance,   "peel-distance",   "Skin",    "Peel by distance (round)",           kNone,                       1, 1,  peelDistanceN, peelDistanceAt,    hasModel,    nullptr},

  {ActionId::kXray,           "xray",            nullptr,   "X-ray along an axis",                kNone,                       2, 2,  nullptr,       xrayAlong,         hasSection,  nullptr},

  {ActionId::kSplitBodies,    "split-bodies",    "Parts",   "Split into bodies",                  kNone,                       1, 1,  splitBodies,   splitBodiesWith,   canSplit,    nullptr},
  {ActionId::kAddPart,        "add-part",        "Parts",   "Add part from file...",              kNone,                       1, -1, addPartDialog, addPartPath,       canAddPart,  nullptr},
  {ActionId::kPartBoolean,    "part-boolean",    "Parts",   "Boolean of the two selected parts",  kNone,                       1, 3,  booleanSelected, booleanWith,     hasParts,    nullptr},
  {ActionId::kRemovePart,     "remove-part",     "Parts",   "Remove the selected part",           kNone,                       1, 1,  removeSelected, removeAt,         hasParts,    nullptr},
  {ActionId::kInterference,   "interference",    "Parts",   "Find interference",                  kNone,                       0, 0,  findInterferenceNow, nullptr,     hasParts,    nullptr},
  {ActionId::kCancelInterference, "cancel-interference", nullptr, "Cancel finding interference", kNone,                     0, 0,  cancelInterferenceNow, nullptr,   interferenceRunning, nullptr},
  {ActionId::kClearance,      "clearance",       "Parts",   "Clearance of the two selected parts", kNone,                      2, 2,  clearanceSelected, clearanceAt,   hasParts,    nullptr},
  {ActionId::kInterferencePair, "interference-pair", nullptr, "Show an interference pair",        kNone,                       1, 1,  nullptr,       showPairAt,        hasInterference, nullptr},
  {ActionId::kInterferenceContact, "contact",      nullptr,   "Contact: overlaps this thin only touch", kNone,                     1, 1,  nullptr,       contactAt,         hasParts,    nullptr},
  {ActionId::kSelectPart,     "select-part",     nullptr,   "Select parts",                       kNone,                       1, -1, nullptr,       selectPartsAt,     hasParts,    nullptr},
  {ActionId::kPartVisible,    "part-visible",    nullptr,   "Show or hide a part",                kNone,                       2, 2,  nullptr,       partVisibleAt,     hasParts,    nullptr},
  {ActionId::kPartsScope,     "parts-scope",     nullptr,   "Section, X-ray and mass on",         kNone,                       1, 1,  nullptr,       partsScopeAt,      hasParts,    nullptr},
  {ActionId::kPlacePart,      "place-part",      nullptr,   "Move and turn a part",               kNone,                       4, 7,  nullptr,       placePartAt,       hasParts,    nullptr},
  {ActionId::kTurnPart,       "turn-part",       nullptr,   "Turn a part by 90 degrees",          kNone,                       2, 2,  nullptr,       turnPartAt,        hasParts,    nullptr},
  {ActionId::kPartColour,     "part-colour",     nullptr,   "Colour of a part",                   kNone,                       2, 5,  nullptr,       partColourAt,      hasParts,    nullptr},

  {ActionId::kControls,       "controls",        "Help",    "Mouse and keyboard",                 {GLFW_KEY_F1, 0},            0, 0,  controls,      nullptr,           nullptr,     nullptr},
  {ActionId::kTerms,          "terms",           "Help",    "Terms...",                           kNone,                       0, -1, terms,         termsAt,           nullptr,     nullptr},
  {ActionId::kAbout,          "about",           "Help",    "About voxmod",                       kNone,                       0, 0,  about,         nullptr,           nullptr,     nullptr},
  {ActionId::kCloseDialogs,   "close-dialogs",   nullptr,   "Close the open dialog",              kNone,                       0, 0,  closeDialogs,  nullptr,           nullptr,     nullptr},
};
// clang-format on

Error notNow(const Action& a, const std::string& why) {
  return makeError(ErrorCode::kInvalidArgument, std::string("'") + a.name + "' " + why);
}

}  // namespace

std::span<const Action> actionTable() { return kActions; }

const Action& action(ActionId id) {
  for (const Action& a : kActions) {
    if (a.id == id) return a;
  }
  assert(false && "every ActionId has a table entry");
  return kActions[0];
}

const Action* findAction(const std::string& name) {
  for (const Action& a : kActions) {
    if (name == a.name) return &a;
  }
  return nullptr;
}

bool actionEnabled(const AppState& state, const Action& a) { return !a.enabled || a.enabled(state); }

bool dispatch(AppState& state, ActionId id) { return dispatch(state, id, ActionArgs{}).ok(); }

Status dispatch(AppState& state, ActionId id, const ActionArgs& args) { return dispatch(state, action(id), args); }

namespace {

Status runAction(AppState& state, const Action& a, const ActionArgs& args) {
  if (a.checked && args.words.size() == 1) {  // a toggle set on or off
    const std::string& w = args.words[0];
    const bool on = w == "on" || w == "1" || w == "true";
    if (!on && w != "off" && w != "0" && w != "false") return notNow(a, "takes on or off");
    if (a.checked(state) != on) a.run(state);
  } else if (args.words.empty() && a.run) {
    a.run(state);
  } else if (!a.run_with) {
    return notNow(a, args.words.empty() ? "needs values" : "takes no values");
  } else {
    const int n = int(args.words.size());
    if (n < a.min_values || (a.max_values >= 0 && n > a.max_values)) return notNow(a, "has the wrong number of values");
    if (Status s = a.run_with(state, args); !s) return s;
  }
  state.redraw_frames = std::max(state.redraw_frames, 2);
  return Ok{};
}

// The document as it was before an action that threw: the model shown and its parts follow it.
void restoreDocument(AppState& state, Document before) {
  state.doc = std::move(before);
  if (state.doc.model) {
    state.model = state.doc.model->grid;
    state.model_version = state.doc.model->version;
    applyPartsScope(state);
  }
  state.viewport.dirty = true;
}

// Runs `run` now. An exception (memory it could not have, a fault in voxmod) becomes its error, and the document is
// as it was before: no action ends the process or leaves half a change behind.
Status runGuarded(AppState& state, const std::string& what, const std::function<Status(AppState&)>& run) {
  Document before = state.doc;  // a cheap copy: grid layers are shared
  try {
    return run(state);
  } catch (const std::bad_alloc&) {
    restoreDocument(state, std::move(before));
    return makeError(ErrorCode::kLimit,
                     "'" + what + "' needs more memory than this machine can give; nothing was changed");
  } catch (const std::exception& e) {
    restoreDocument(state, std::move(before));
    return makeError(ErrorCode::kInvalidArgument,
                     "'" + what + "' failed (" + std::string(e.what()) + "); nothing was changed");
  }
}

Status runGuarded(AppState& state, const Action& a, const ActionArgs& args) {
  return runGuarded(state, a.label, [&](AppState& s) { return runAction(s, a, args); });
}

}  // namespace

Status dispatch(AppState& state, const Action& a, const ActionArgs& args) {
  if (!actionEnabled(state, a)) return notNow(a, "is not available now");
  if (!state.building_frame) return runGuarded(state, a, args);
  // A widget's action waits until the frame is built: the frame goes on drawing from the state it started with.
  state.deferred_actions.push_back([&a, args](AppState& s) {
    if (!actionEnabled(s, a)) return;  // no longer available by the time it runs, as a disabled button's click
    if (Status st = runGuarded(s, a, args); !st) reportError(s, st.error().message);
  });
  state.redraw_frames = std::max(state.redraw_frames, 2);
  return Ok{};
}

void runBetweenFrames(AppState& state, const std::string& what, std::function<void(AppState&)> run) {
  auto guarded = [what, run = std::move(run)](AppState& s) {
    const Status st = runGuarded(s, what, [&](AppState& t) {
      run(t);
      return Status(Ok{});
    });
    if (!st) reportError(s, st.error().message);
  };
  if (state.building_frame) {
    state.deferred_actions.push_back(std::move(guarded));
    state.redraw_frames = std::max(state.redraw_frames, 2);
  } else {
    guarded(state);
  }
}

void runDeferredActions(AppState& state) {
  std::vector<std::function<void(AppState&)>> queue = std::move(state.deferred_actions);
  state.deferred_actions.clear();
  for (auto& run : queue) run(state);
}

void dispatchValues(AppState& state, ActionId id, std::vector<std::string> words) {
  const Status s = dispatch(state, id, ActionArgs{std::move(words), {}});
  (void)s;
}

std::string disabledReason(const AppState& state, const Action& a) {
  if (actionEnabled(state, a)) return {};
  const auto needs = [](const char* what, ActionId panel) {
    const Action& p = action(panel);
    return std::string("Needs ") + what + ": open the " + p.label + " (" + shortcutText(p.shortcut) +
           ") and let it finish";
  };
  if (!state.doc.model) return {};  // no model: every export is off for the same plain reason
  switch (a.id) {
    case ActionId::kExportThickness:
      return needs("the thickness", ActionId::kPanelThickness);
    case ActionId::kExportDepth:
      return needs("the skin layers", ActionId::kPanelSkin);
    case ActionId::kExportXrayPng:
    case ActionId::kExportXrayCsv:
    case ActionId::kExportXrayVolume:
      return needs("the X-ray", ActionId::kPanelXray);
    default:
      return {};
  }
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
    case GLFW_KEY_EQUAL:
      return t + "=";
    case GLFW_KEY_MINUS:
      return t + "-";
    default:
      break;
  }
  if ((s.key >= GLFW_KEY_A && s.key <= GLFW_KEY_Z) || (s.key >= GLFW_KEY_0 && s.key <= GLFW_KEY_9)) {
    return t + char(s.key);  // GLFW key codes of letters and digits are their ASCII codes
  }
  return t + "?";
}

}  // namespace vox::app
