#pragma once
// The one table of things the user can do (id, name, menu, label, shortcut, function). The menu bar, the keyboard
// shortcuts and the script (--script) are all generated from it, and panels' buttons dispatch its entries, so a
// command is defined once and every way of giving it reaches the same function. Entries are listed in menu order.
//
// An action runs without values (a menu item, a shortcut, a button: `run`) or with them (a script line, a panel that
// already has them: `run_with`), e.g. "open" shows the file browser, "open part.stl" opens that file; "peel" peels the
// Skin panel's N layers, "peel 3" three. A toggle given "on" or "off" is set to that.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "app/app_state.h"
#include "vox/core/result.h"

namespace vox::app {

enum class ActionId {
  kOpen,
  kSave,
  kSaveAs,
  kSaveParts,
  kRecoverAutosave,
  kDiscardAutosave,
  kExportBinvox,
  kExportSurface,
  kExportSmoothSurface,
  kExportViewPng,
  kExportSectionPng,
  kExportXrayPng,
  kExportXrayCsv,
  kExportVolume,
  kExportThickness,
  kExportDepth,
  kExportXrayVolume,
  kExportReport,
  kExportSize,
  kQuit,
  kUndo,
  kRedo,
  kMeasureClear,
  kMeasure,
  kVoxelize,
  kModelUnits,
  kCancelJob,
  kViewFit,
  kViewIso,
  kViewPosX,
  kViewNegX,
  kViewPosY,
  kViewNegY,
  kViewPosZ,
  kViewNegZ,
  kViewOrtho,
  kViewAngles,
  kZoomIn,
  kZoomOut,
  kZoom,
  kViewLit,
  kViewRound,
  kViewLod,
  kViewCut,
  kViewDisputed,
  kPanelModel,
  kPanelSection,
  kPanelSkin,
  kPanelXray,
  kPanelMass,
  kPanelThickness,
  kPanelParts,
  kPanelPrint,
  kPrintDirection,
  kOverhangAngle,
  kPrintOrient,
  kPrintOrientation,
  kPrintCavity,
  kPrintLayFace,
  kComputePrint,
  kCancelPrint,
  kPanelCasting,
  kCastingAlloy,
  kCastingMould,
  kCastingSuperheat,
  kCastingMouldTemperature,
  kCastingFeeder,
  kCastingPlaceFeeder,
  kCastingDeleteFeeder,
  kSimulateCasting,
  kCancelCasting,
  kCastingField,
  kCastingTime,
  kCastingPlay,
  kCastingHotSpot,
  kMinWall,
  kMinArea,
  kThicknessMethod,
  kThinRegion,
  kHotSpot,
  kComputeThickness,
  kCancelThickness,
  kCancelRays,
  kSectionPrev,
  kSectionNext,
  kSectionPlay,
  kSectionAt,
  kSectionZoom,
  kSectionPlane,
  kSectionPlaneThrough,
  kPeelOne,
  kPeelN,
  kPeelBack,
  kPeelCore,
  kPeelReset,
  kPeelDistance,
  kSkinLayers,
  kCancelSkinLayers,
  kXray,
  kSplitBodies,
  kAddPart,
  kPartBoolean,
  kRemovePart,
  kInterference,
  kInterferencePair,
  kInterferenceContact,
  kSelectPart,
  kPartVisible,
  kPartsScope,
  kPlacePart,
  kTurnPart,
  kPartColour,
  kClearance,
  kCancelInterference,
  kControls,
  kTerms,
  kAbout,
  kCloseDialogs,
};

// A key (GLFW_KEY_*) with modifier bits (GLFW_MOD_CONTROL, GLFW_MOD_SHIFT); key 0 = no shortcut.
struct Shortcut {
  int key = 0;
  int mods = 0;
};

// The values an action is given: words, and the text after the action's name (for paths with spaces).
// The most the axis section's picture is zoomed (section-zoom).
inline constexpr double kMaxSectionZoom = 256.0;

struct ActionArgs {
  std::vector<std::string> words;
  std::string rest;
};

struct Action {
  ActionId id;
  const char* name;   // the script's word for it: "open", "peel-core", "view-pos-x"
  const char* menu;   // "File", "Edit", "Model", "View", "Section", "Skin", "Help"; null: not in a menu
  const char* label;  // menu text; "..." when it opens a dialog
  Shortcut shortcut;
  int min_values, max_values;                        // how many words `run_with` takes (-1: any)
  void (*run)(AppState&);                            // without values; null: it needs them
  Status (*run_with)(AppState&, const ActionArgs&);  // with values; the error says why they do not fit
  bool (*enabled)(const AppState&);                  // null: always
  bool (*checked)(const AppState&);                  // null: not a toggle
};

std::span<const Action> actionTable();
const Action& action(ActionId id);
// The action a script word names; null when none does.
const Action* findAction(const std::string& name);
// Runs the action without values when it is enabled; returns whether it ran.
bool dispatch(AppState& state, ActionId id);
// Runs the action with values (none: as dispatch above). Fails, saying why, when the action is not enabled now or
// the values do not fit. A toggle given on|off runs only when it is not already so. An action that throws fails
// with its error and leaves the document as it was.
// While the frame's widgets are drawn (AppState::building_frame) an enabled action is queued instead and runs,
// errors shown in a dialog, in runDeferredActions once the frame is built: a widget's action never changes the state
// the rest of the frame draws from.
Status dispatch(AppState& state, ActionId id, const ActionArgs& args);
Status dispatch(AppState& state, const Action& a, const ActionArgs& args);
// From a panel whose values always fit (an axis it lists, an index in range): as dispatch with them; a refusal
// (the action not enabled now) is ignored, as a disabled menu item's click is.
void dispatchValues(AppState& state, ActionId id, std::vector<std::string> words);
bool actionEnabled(const AppState& state, const Action& a);
// Runs `run` (a dialog's choice that is no action of the table: the unsaved-changes prompt's Save and Discard) as an
// action runs: between frames when a frame is being built, an exception shown as the error of `what` with the
// document left as it was.
void runBetweenFrames(AppState& state, const std::string& what, std::function<void(AppState&)> run);
// Runs the actions the last frame's widgets gave, in order (the frame loop calls it between frames).
void runDeferredActions(AppState& state);
// Why an export that needs a computed result is off now, for its menu item's tooltip, e.g. "Needs the skin layers:
// open the Skin removal panel (Ctrl+3) and let it finish"; empty while it is on, and for the other actions.
std::string disabledReason(const AppState& state, const Action& a);
// "Ctrl+Shift+S"; empty without a shortcut.
std::string shortcutText(const Shortcut& s);

}  // namespace vox::app
