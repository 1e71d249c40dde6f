// Window layout: a menu bar (menu_bar.cpp), the panel tabs on the left, the 3D view (and for sections and X-rays the
// 2D image beside it, image_layout.cpp) filling the rest, and a status bar (status_bar.cpp). ImGui 1.86 from Debian
// has no docking, so the layout is fixed and recomputed from the window size every frame.
#include <algorithm>
#include <string>

#include <imgui.h>

#include "app/panels/panels.h"
#include "app/ui.h"
#include "app/viewport.h"

namespace vox::app {
namespace {

constexpr float kSidebarWidth = 390.0f;

struct PanelEntry {
  Panel panel;
  const char* tab;
  void (*draw)(AppState&);
};
constexpr PanelEntry kPanels[] = {
    {Panel::kModel, "Model", drawModelPanel},       {Panel::kSection, "Section", drawSectionPanel},
    {Panel::kSkin, "Skin", drawSkinPanel},          {Panel::kXray, "X-ray", drawXrayPanel},
    {Panel::kMass, "Mass", drawMassPanel},          {Panel::kThickness, "Thickness", drawThicknessPanel},
    {Panel::kParts, "Parts", drawPartsPanel},       {Panel::kPrint, "Print", drawPrintPanel},
    {Panel::kCasting, "Casting", drawCastingPanel},
};

void drawSidebar(AppState& state, ImVec2 pos, ImVec2 size) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin("##sidebar", nullptr, kFixedWindow);
  if (ImGui::BeginTabBar("panels")) {
    for (const PanelEntry& e : kPanels) {
      const bool select = state.panel_change_requested && state.panel == e.panel;
      if (ImGui::BeginTabItem(e.tab, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0)) {
        markWidget(std::string("tab_") + panelName(e.panel));
        // The tab bar reports the user's clicks; a requested change wins for the frame it is made.
        if (!state.panel_change_requested) state.panel = e.panel;
        ImGui::Spacing();
        e.draw(state);
        ImGui::EndTabItem();
      } else {
        markWidget(std::string("tab_") + panelName(e.panel));
      }
    }
    ImGui::EndTabBar();
  }
  state.panel_change_requested = false;
  ImGui::End();
}

}  // namespace

void drawFrame(AppState& state) {
  drawMainMenu(state);
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float top = vp->Pos.y + ImGui::GetFrameHeight();
  const float status_h = ImGui::GetFrameHeight() + 6.0f;
  const float body_h = std::max(1.0f, vp->Size.y - ImGui::GetFrameHeight() - status_h);
  const float sidebar_w = std::min(kSidebarWidth, vp->Size.x * 0.45f);

  drawSidebar(state, ImVec2(vp->Pos.x, top), ImVec2(sidebar_w, body_h));

  const float main_x = vp->Pos.x + sidebar_w;
  const float main_w = std::max(1.0f, vp->Size.x - sidebar_w);
  const ImageLayout layout = layoutImage(state, main_w, body_h);

  ImGui::SetNextWindowPos(ImVec2(main_x, top));
  ImGui::SetNextWindowSize(layout.view);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
  ImGui::Begin("##view", nullptr, kFixedWindow | ImGuiWindowFlags_NoScrollWithMouse);
  drawViewport(state);
  ImGui::End();
  ImGui::PopStyleVar();

  if (layout.image.x > 0.0f) {
    ImGui::SetNextWindowPos(ImVec2(main_x + layout.image_offset.x, top + layout.image_offset.y));
    ImGui::SetNextWindowSize(layout.image);
    ImGui::Begin("##image", nullptr, kFixedWindow | ImGuiWindowFlags_NoScrollWithMouse);
    if (state.panel == Panel::kSection || state.panel == Panel::kParts || state.panel == Panel::kPrint) {
      drawSectionImage(state);
    } else if (state.panel == Panel::kThickness) {
      drawThicknessImage(state);
    } else if (state.panel == Panel::kCasting) {
      drawCastingImage(state);
    } else {
      drawXrayImage(state);
    }
    ImGui::End();
  }

  drawStatusBar(state);
  drawJobWindow(state);
  drawVoxelizeDialog(state);
  drawFileBrowser(state);
  drawUnsavedPrompt(state);
  drawRecoveryOffer(state);
  drawAboutDialog(state);
  drawControlsDialog(state);
  drawTermsDialog(state);
  // Last: an error raised by another dialog this frame shows on top of it; the file browser shows its own errors.
  if (!fileBrowserOpen()) drawErrorDialog(state);
  state.close_dialogs = false;
  handleShortcuts(state);
}

}  // namespace vox::app
