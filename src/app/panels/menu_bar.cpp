// The menu bar, generated from the action table, with Open Recent under File > Open; and the keyboard shortcuts of
// the same table.
#include <string>

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"

namespace vox::app {

void drawMainMenu(AppState& state) {
  if (!ImGui::BeginMainMenuBar()) return;
  const char* current_menu = nullptr;
  bool menu_open = false;
  for (const Action& a : actionTable()) {
    if (!a.menu) continue;  // given values by a script or a panel only
    if (!current_menu || std::string(current_menu) != a.menu) {
      if (menu_open) ImGui::EndMenu();
      current_menu = a.menu;
      menu_open = ImGui::BeginMenu(a.menu);
    }
    if (!menu_open) continue;
    const std::string sc = shortcutText(a.shortcut);
    std::string label = a.label;
    if (a.id == ActionId::kUndo && !state.doc.undo_stack.empty()) label += " " + state.doc.model->label;
    if (a.id == ActionId::kRedo && !state.doc.redo_stack.empty()) label += " " + state.doc.redo_stack.back().label;
    if (ImGui::MenuItem(label.c_str(), sc.empty() ? nullptr : sc.c_str(), a.checked ? a.checked(state) : false,
                        actionEnabled(state, a))) {
      dispatch(state, a.id);
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      if (const std::string why = disabledReason(state, a); !why.empty()) ImGui::SetTooltip("%s", why.c_str());
    }
    if (a.id == ActionId::kOpen) {
      // Open Recent sits under Open; its entries are files, not actions.
      if (ImGui::BeginMenu("Open Recent", !state.settings.recent_files.empty())) {
        std::string chosen;
        for (const std::string& f : state.settings.recent_files) {
          if (ImGui::MenuItem(f.c_str())) chosen = f;
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Clear list")) state.settings.recent_files.clear();
        ImGui::EndMenu();
        if (!chosen.empty()) requestOpen(state, chosen);
      }
    }
    if (a.id == ActionId::kSaveParts || a.id == ActionId::kExportXrayCsv || a.id == ActionId::kCancelJob ||
        a.id == ActionId::kViewNegZ || a.id == ActionId::kZoomOut || a.id == ActionId::kViewDisputed ||
        a.id == ActionId::kRedo || a.id == ActionId::kExportXrayVolume) {
      ImGui::Separator();
    }
  }
  if (menu_open) ImGui::EndMenu();
  ImGui::EndMainMenuBar();
}

void handleShortcuts(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) return;
  for (const auto& [key, key_mods] : state.key_presses) {
    const int mods = key_mods & (GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT);
    for (const Action& a : actionTable()) {
      if (a.shortcut.key == key && a.shortcut.mods == mods) {
        dispatch(state, a.id);
        break;
      }
    }
  }
}

}  // namespace vox::app
