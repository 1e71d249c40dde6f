// A plain file browser (Debian ships no ImGui file dialog): the directory's folders and matching files in a list,
// a path field, and a file-name field for saving. The listing and the widgets that move through it are
// file_listing.cpp; listing happens when the directory or the filter changes.
#include <algorithm>
#include <string>
#include <system_error>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {
namespace {

constexpr const char* kPopup = "File browser";

void accept(AppState& state) {
  FileBrowser& b = state.browser;
  std::filesystem::path name = b.file_name;
  const std::vector<std::string>& extensions = b.extensions;  // none: a folder's name
  if (b.saving && !name.empty() && !extensions.empty() && !matchesExtension(name.string(), extensions)) {
    name += extensions.front();  // "part" -> "part.vxm"
  }
  const std::filesystem::path path = name.is_absolute() ? name : b.directory / name;
  // Between frames, as every action: the browser closes on the next frame when it went through, and stays open with
  // the error over it when it did not.
  runBetweenFrames(state, b.title, [action = b.action, path](AppState& s) {
    if (givePath(s, action, path) && !s.browser.open_requested) s.browser.accepted = true;
  });
}

}  // namespace

bool fileBrowserOpen() { return ImGui::IsPopupOpen(kPopup); }

void drawFileBrowser(AppState& state) {
  FileBrowser& b = state.browser;
  if (b.open_requested) {
    b.open_requested = false;
    b.needs_listing = true;
    ImGui::OpenPopup(kPopup);
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(760.0f, vp->Size.x - 40.0f), std::min(520.0f, vp->Size.y - 40.0f)),
                           ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(kPopup, nullptr)) return;
  if (b.accepted) {  // the file chosen last frame went through
    b.accepted = false;
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  if (b.needs_listing || b.listed_directory != b.directory || b.listed_all_files != b.show_all_files) listDirectory(b);

  ImGui::TextUnformatted(b.title.c_str());
  drawBrowserNavigation(b);

  const float footer = ImGui::GetFrameHeightWithSpacing() * (b.action == ActionId::kExportViewPng ? 3.0f : 2.0f) +
                       ImGui::GetStyle().ItemSpacing.y;
  bool activate = drawBrowserEntries(b, footer);

  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 260.0f);
  if (widget::InputText("##name", &b.file_name, ImGuiInputTextFlags_EnterReturnsTrue)) activate = true;
  ImGui::SameLine();
  widget::Checkbox("All files", &b.show_all_files);
  ImGui::SameLine();
  if (widget::Button(b.saving ? "Save" : "Open", ImVec2(80.0f, 0.0f))) activate = true;
  ImGui::SameLine();
  // Escape closes the browser, unless it is closing an error shown over it.
  const bool escape = state.errors.messages.empty() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if (widget::Button("Cancel", ImVec2(80.0f, 0.0f)) || state.close_dialogs || escape) {
    b.then = nullptr;
    ImGui::CloseCurrentPopup();
  } else if (activate && !b.file_name.empty()) {
    accept(state);
  }
  if (b.action == ActionId::kExportViewPng) {
    // The picture's own size, whatever the window's (e.g. 3840 x 2160 for a slide); 0 x 0 is the view as shown.
    int size[2] = {state.export_width, state.export_height};
    ImGui::SetNextItemWidth(160.0f);
    if (widget::InputInt2("pixels (0: as shown)", size)) {
      state.export_width = std::clamp(size[0], 0, 8192);
      state.export_height = std::clamp(size[1], 0, 8192);
    }
  }
  std::error_code ec;
  const bool folder = b.extensions.empty();  // the name is a folder's (save each part)
  if (folder && !b.file_name.empty() && std::filesystem::is_directory(b.directory / b.file_name, ec)) {
    ImGui::TextDisabled("%s exists: files of the same names in it will be replaced.", b.file_name.c_str());
  } else if (b.saving && !b.file_name.empty() && std::filesystem::exists(b.directory / b.file_name, ec)) {
    ImGui::TextDisabled("%s exists and will be replaced.", b.file_name.c_str());
  } else if (folder) {
    ImGui::TextDisabled("Showing folders; the folder named above is made when missing");
  } else {
    std::string exts;
    for (const std::string& e : b.extensions) exts += (exts.empty() ? "" : ", ") + e;
    ImGui::TextDisabled("Showing %s", b.show_all_files ? "all files" : exts.c_str());
  }
  // An error raised here (a file that cannot be written) opens over the browser, inside its popup: opened at the
  // top level it would close the browser, and the name typed with it.
  drawErrorDialog(state);
  ImGui::EndPopup();
}

}  // namespace vox::app
