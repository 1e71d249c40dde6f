#pragma once
// The one table of things the user can do (id, menu, label, shortcut, function). The menu bar and the keyboard
// shortcuts are both generated from it, and panels' buttons dispatch its entries, so a command is defined once.
// Entries are listed in menu order.
#include <span>
#include <string>

#include "app/app_state.h"

namespace vox::app {

enum class ActionId {
  kOpen,
  kSave,
  kSaveAs,
  kExportBinvox,
  kExportViewPng,
  kExportSectionPng,
  kExportXrayPng,
  kExportXrayCsv,
  kQuit,
  kUndo,
  kRedo,
  kVoxelize,
  kCancelJob,
  kViewFit,
  kViewIso,
  kViewPosX,
  kViewNegX,
  kViewPosY,
  kViewNegY,
  kViewPosZ,
  kViewNegZ,
  kViewLit,
  kViewRound,
  kViewLod,
  kViewDisputed,
  kPanelModel,
  kPanelSection,
  kPanelSkin,
  kPanelXray,
  kPanelMass,
  kSectionPrev,
  kSectionNext,
  kSectionPlay,
  kPeelOne,
  kPeelN,
  kPeelBack,
  kPeelCore,
  kPeelReset,
  kControls,
  kAbout,
};

// A key (GLFW_KEY_*) with modifier bits (GLFW_MOD_CONTROL, GLFW_MOD_SHIFT); key 0 = no shortcut.
struct Shortcut {
  int key = 0;
  int mods = 0;
};

struct Action {
  ActionId id;
  const char* menu;   // "File", "Edit", "Model", "View", "Section", "Skin", "Help"
  const char* label;  // menu text; "..." when it opens a dialog
  Shortcut shortcut;
  void (*run)(AppState&);
  bool (*enabled)(const AppState&);  // null: always
  bool (*checked)(const AppState&);  // null: not a toggle
};

std::span<const Action> actionTable();
const Action& action(ActionId id);
// Runs the action when it is enabled; returns whether it ran.
bool dispatch(AppState& state, ActionId id);
bool actionEnabled(const AppState& state, const Action& a);
// "Ctrl+Shift+S"; empty without a shortcut.
std::string shortcutText(const Shortcut& s);

}  // namespace vox::app
