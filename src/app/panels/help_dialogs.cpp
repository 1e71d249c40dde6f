// Help > Mouse and keyboard (the mouse controls and every shortcut of the action table), Help > Terms (glossary.h) and
// Help > About.
#include <string>

#include <imgui.h>

#include "vox/render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/actions.h"
#include "app/glossary.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {

void drawControlsDialog(AppState& state) {
  if (state.help.show_controls) {
    state.help.show_controls = false;
    ImGui::OpenPopup("Mouse and keyboard");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Mouse and keyboard", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  static constexpr const char* kMouse[][2] = {
      {"Left drag", "orbit the 3D view"},
      {"Right or middle drag, Shift+left drag", "pan"},
      {"Wheel", "zoom"},
      {"Double-click", "fit the model in the view"},
      {"Ctrl+click in the 3D view", "pick a voxel to measure (two: their distance)"},
      {"Click in the section or thickness image", "pick a voxel to measure (snapped to the edge; Alt: as is)"},
      {"Hover the section or X-ray image", "read the voxel or ray under the cursor"},
      {"Wheel, right drag over the section or thickness image", "zoom about the cursor, pan"},
  };
  const auto row = [](const char* what, const std::string& does) {  // unwrapped: the window sizes itself to fit
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", what);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(does.c_str());
  };
  if (ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& r : kMouse) row(r[0], r[1]);
    // Every shortcut from the action table, so the list is never out of date.
    for (const Action& a : actionTable()) {
      const std::string sc = shortcutText(a.shortcut);
      if (!sc.empty()) row(sc.c_str(), std::string(a.menu) + " > " + a.label);
    }
    ImGui::EndTable();
  }
  if (widget::Button("Close", ImVec2(120.0f, 0.0f)) || state.close_dialogs ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void drawTermsDialog(AppState& state) {
  HelpUi& help = state.help;
  if (help.show_terms) {
    help.show_terms = false;
    help.scroll_to_term = !help.term.empty();
    ImGui::OpenPopup("Terms");
  }
  centreNextWindow();
  const float em = ImGui::GetFontSize();
  ImGui::SetNextWindowSize(ImVec2(em * 40.0f, 0.0f));
  if (!ImGui::BeginPopupModal("Terms", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::BeginChild("terms", ImVec2(0.0f, em * 28.0f), true);
  for (const Term& t : glossary()) {
    const bool chosen = help.term == t.key;
    ImGui::PushStyleColor(ImGuiCol_Text, chosen ? ImVec4(1.0f, 0.8f, 0.3f, 1.0f) : ImVec4(0.55f, 0.75f, 1.0f, 1.0f));
    ImGui::TextUnformatted(t.name);
    ImGui::PopStyleColor();
    markWidget(std::string("term ") + t.key);
    if (chosen && help.scroll_to_term) {
      ImGui::SetScrollHereY(0.0f);
      help.scroll_to_term = false;
    }
    ImGui::TextWrapped("%s", t.text);
    ImGui::Spacing();
  }
  ImGui::EndChild();
  if (widget::Button("Close", ImVec2(120.0f, 0.0f)) || state.close_dialogs ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void drawAboutDialog(AppState& state) {
  if (state.help.show_about) {
    state.help.show_about = false;
    ImGui::OpenPopup("About voxmod");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("About voxmod", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted("voxmod: a voxel solid modeler");
  ImGui::TextDisabled("After the thesis 'Voxel based solid models' (2005): scan-line voxelization into Z bit-plane");
  ImGui::TextDisabled("layers, points shaded by their face-neighbour code, sections, skin removal and X-ray scans.");
  ImGui::Spacing();
  ImGui::Text("Dear ImGui %s, GLFW %s", ImGui::GetVersion(), glfwGetVersionString());
  ImGui::Text("OpenGL: %s", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  if (widget::Button("Close", ImVec2(120.0f, 0.0f)) || state.close_dialogs ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace vox::app
