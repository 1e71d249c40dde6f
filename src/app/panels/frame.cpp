// Window layout: a menu bar, the panel tabs on the left, the 3D view (and for sections and X-rays the 2D image
// beside it) filling the rest, and a status bar. ImGui 1.86 from Debian has no docking, so the layout is fixed and
// recomputed from the window size every frame.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "app/viewport.h"

namespace vox::app {
namespace {

constexpr float kSidebarWidth = 390.0f;
constexpr ImGuiWindowFlags kFixedWindow = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                          ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

struct PanelEntry {
  Panel panel;
  const char* tab;
  void (*draw)(AppState&);
};
constexpr PanelEntry kPanels[] = {
    {Panel::kModel, "Model", drawModelPanel}, {Panel::kSection, "Section", drawSectionPanel},
    {Panel::kSkin, "Skin", drawSkinPanel},    {Panel::kXray, "X-ray", drawXrayPanel},
    {Panel::kMass, "Mass", drawMassPanel},
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

// How the main area is shared between the 3D view and the 2D image of the Section and X-ray panels: beside or
// below the view, whichever shows the image larger, with the image taking the room it can use (35-60%).
struct ImageLayout {
  ImVec2 view;
  ImVec2 image{0.0f, 0.0f};  // zero: no image
  ImVec2 image_offset{0.0f, 0.0f};
};

// Magnification of an image made of a fixed part (legend, labels) and a part that scales (the voxels), in an area.
// Whole numbers above 1, so every voxel covers the same number of pixels.
float fitScale(ImVec2 fixed, ImVec2 scalable, ImVec2 area) {
  const float s = std::min((area.x - fixed.x) / scalable.x, (area.y - fixed.y) / scalable.y);
  return s >= 1.0f ? std::floor(s) : std::max(s, 0.05f);
}

ImageLayout layoutImage(AppState& state, float w, float h) {
  ImageLayout l;
  l.view = ImVec2(w, h);
  if (state.model.empty() || (state.panel != Panel::kSection && state.panel != Panel::kXray)) return l;
  const float text = 3.0f * ImGui::GetTextLineHeightWithSpacing();  // title and read-out lines around the image
  constexpr float kMost = 0.6f, kLeast = 0.35f;
  ImVec2 fixed(40.0f, text + 16.0f), scalable(1.0f, 1.0f);
  if (state.panel == Panel::kXray) {
    const XrayResult* x = currentXray(state);
    if (!x) return l;  // not computed yet: the whole area for the 3D view
    fixed = ImVec2(xrayLegendSize().x + 40.0f, text + 16.0f);
    scalable = ImVec2(float(x->thickness.width), float(x->thickness.height));
  } else if (const Section* s = currentSection(state)) {
    scalable = ImVec2(float(s->mask.width), float(s->mask.height));
  }
  const float side = fitScale(fixed, scalable, ImVec2(kMost * w, h));
  const float stacked = fitScale(fixed, scalable, ImVec2(w, kMost * h));
  if (stacked >= side) {
    const float ih = std::clamp(fixed.y + scalable.y * stacked, kLeast * h, kMost * h);
    l.image = ImVec2(w, std::floor(ih));
    l.view = ImVec2(w, h - l.image.y);
    l.image_offset = ImVec2(0.0f, l.view.y);
  } else {
    const float iw = std::clamp(fixed.x + scalable.x * side, kLeast * w, kMost * w);
    l.image = ImVec2(std::floor(iw), h);
    l.view = ImVec2(w - l.image.x, h);
    l.image_offset = ImVec2(l.view.x, 0.0f);
  }
  return l;
}

}  // namespace

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
    if (a.id == ActionId::kSaveAs || a.id == ActionId::kExportXrayCsv || a.id == ActionId::kCancelJob ||
        a.id == ActionId::kViewNegZ || a.id == ActionId::kZoomOut || a.id == ActionId::kViewDisputed ||
        a.id == ActionId::kRedo) {
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

void drawStatusBar(AppState& state) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float h = ImGui::GetFrameHeight() + 6.0f;
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
  ImGui::Begin("##status", nullptr, kFixedWindow);
  if (state.load_job.active() || state.voxelize_job.active()) {
    const std::string label = state.load_job.active() ? state.load_job.label() : state.voxelize_job.label();
    const double p = state.load_job.active() ? state.load_job.progress() : state.voxelize_job.progress();
    ImGui::TextUnformatted(label.c_str());
    ImGui::SameLine();
    ImGui::ProgressBar(float(p), ImVec2(200.0f, 0.0f));
  } else if (!state.status_message.empty() && nowSeconds() - state.status_since < 8.0) {
    ImGui::TextUnformatted(state.status_message.c_str());
  } else if (!state.model.empty()) {
    const VoxelGrid& g = state.model;
    const SurfaceStats* stats = state.surface_stats.get(state.model_version);
    ImGui::Text("%s   %d x %d x %d voxels   voxel %s   %s filled", state.doc.path.filename().string().c_str(), g.nx(),
                g.ny(), g.nz(), formatLength(g.voxelSize(), g.frame().units).c_str(),
                stats ? groupDigits(stats->filled).c_str() : "...");
  } else if (state.doc.mesh) {
    ImGui::Text("%s   %s triangles, not voxelized yet (Model > Voxelize...)",
                state.doc.path.filename().string().c_str(),
                groupDigits(int64_t(state.doc.mesh->mesh.triangles.size())).c_str());
  } else {
    ImGui::TextUnformatted("No file open");
  }
  char fps[48];
  std::snprintf(fps, sizeof fps, "%.1f fps", state.fps);
  ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(fps).x - 12.0f);
  ImGui::TextDisabled("%s", fps);
  ImGui::End();
  ImGui::PopStyleVar();
}

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
    if (state.panel == Panel::kSection) {
      drawSectionImage(state);
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
  drawAboutDialog(state);
  drawControlsDialog(state);
  // Last: an error raised by another dialog this frame shows on top of it; the file browser shows its own errors.
  if (!fileBrowserOpen()) drawErrorDialog(state);
  state.close_dialogs = false;
  handleShortcuts(state);
}

}  // namespace vox::app
