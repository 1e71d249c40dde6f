// A plain file browser (Debian ships no ImGui file dialog): the directory's folders and matching files in a list,
// a path field, and a file-name field for saving. Listing happens when the directory or the filter changes.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>
#include <system_error>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {
namespace {

constexpr const char* kPopup = "File browser";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool matches(const std::string& name, const std::vector<std::string>& extensions) {
  const std::string l = lower(name);
  return std::any_of(extensions.begin(), extensions.end(), [&](const std::string& e) {
    return l.size() > e.size() && l.compare(l.size() - e.size(), e.size(), e) == 0;
  });
}

void list(FileBrowser& b) {
  b.entries.clear();
  b.error.clear();
  b.listed_directory = b.directory;
  b.listed_all_files = b.show_all_files;
  b.needs_listing = false;
  const std::vector<std::string> ext = browserExtensions(b.purpose);
  std::error_code ec;
  std::filesystem::directory_iterator it(b.directory, std::filesystem::directory_options::skip_permission_denied, ec);
  if (ec) {
    b.error = b.directory.string() + ": " + ec.message();
    return;
  }
  for (; it != std::filesystem::directory_iterator(); it.increment(ec)) {
    if (ec) {
      b.error = b.directory.string() + ": " + ec.message();
      break;
    }
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;  // hidden files, as file dialogs do by default
    std::error_code e2;
    const bool dir = it->is_directory(e2);
    if (!dir && !b.show_all_files && !matches(name, ext)) continue;
    FileBrowser::Entry entry{name, dir, 0};
    if (!dir) entry.size = it->file_size(e2);
    b.entries.push_back(std::move(entry));
  }
  std::sort(b.entries.begin(), b.entries.end(), [](const FileBrowser::Entry& x, const FileBrowser::Entry& y) {
    if (x.is_directory != y.is_directory) return x.is_directory;
    return lower(x.name) < lower(y.name);
  });
}

bool isSave(BrowserPurpose p) { return p != BrowserPurpose::kOpen; }

void accept(AppState& state) {
  FileBrowser& b = state.browser;
  std::filesystem::path name = b.file_name;
  if (isSave(b.purpose) && !name.empty() && !matches(name.string(), browserExtensions(b.purpose))) {
    name += browserExtensions(b.purpose).front();  // "part" -> "part.vxm"
  }
  const std::filesystem::path path = name.is_absolute() ? name : b.directory / name;
  if (acceptBrowserPath(state, b.purpose, path)) ImGui::CloseCurrentPopup();
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
  if (b.needs_listing || b.listed_directory != b.directory || b.listed_all_files != b.show_all_files) list(b);

  ImGui::TextUnformatted(browserTitle(b.purpose));
  if (ImGui::Button("Up")) {
    b.directory = b.directory.parent_path();
    b.needs_listing = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Home")) {
    if (const char* home = std::getenv("HOME")) b.directory = home;
    b.needs_listing = true;
  }
  ImGui::SameLine();
  std::string dir_text = b.directory.string();
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputText("##dir", &dir_text, ImGuiInputTextFlags_EnterReturnsTrue)) {
    b.directory = dir_text;
    b.needs_listing = true;
  }

  const float footer =
      ImGui::GetFrameHeightWithSpacing() * (b.purpose == BrowserPurpose::kExportViewPng ? 3.0f : 2.0f) +
      ImGui::GetStyle().ItemSpacing.y;
  bool activate = false;
  if (ImGui::BeginChild("##entries", ImVec2(0.0f, -footer), true)) {
    if (!b.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", b.error.c_str());
    for (const FileBrowser::Entry& e : b.entries) {
      const std::string label = e.is_directory ? "[dir]  " + e.name + "/" : "       " + e.name;
      const bool selected = !e.is_directory && e.name == b.file_name;
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (e.is_directory) {
          if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
            b.directory /= e.name;
            b.needs_listing = true;
          }
        } else {
          b.file_name = e.name;
          if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) activate = true;
        }
      }
      if (!e.is_directory) {
        ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 90.0f);
        ImGui::TextDisabled("%s", formatBytes(e.size).c_str());
      }
    }
    if (b.entries.empty() && b.error.empty()) ImGui::TextDisabled("No matching files here.");
  }
  ImGui::EndChild();

  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 260.0f);
  if (ImGui::InputText("##name", &b.file_name, ImGuiInputTextFlags_EnterReturnsTrue)) activate = true;
  ImGui::SameLine();
  ImGui::Checkbox("All files", &b.show_all_files);
  ImGui::SameLine();
  if (ImGui::Button(isSave(b.purpose) ? "Save" : "Open", ImVec2(80.0f, 0.0f))) activate = true;
  ImGui::SameLine();
  // Escape closes the browser, unless it is closing an error shown over it.
  const bool escape = state.errors.messages.empty() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if (ImGui::Button("Cancel", ImVec2(80.0f, 0.0f)) || state.close_dialogs || escape) {
    b.then = nullptr;
    ImGui::CloseCurrentPopup();
  } else if (activate && !b.file_name.empty()) {
    accept(state);
  }
  if (b.purpose == BrowserPurpose::kExportViewPng) {
    // The picture's own size, whatever the window's (e.g. 3840 x 2160 for a slide); 0 x 0 is the view as shown.
    int size[2] = {state.export_width, state.export_height};
    ImGui::SetNextItemWidth(160.0f);
    if (ImGui::InputInt2("pixels (0: as shown)", size)) {
      state.export_width = std::clamp(size[0], 0, 8192);
      state.export_height = std::clamp(size[1], 0, 8192);
    }
  }
  std::error_code ec;
  if (isSave(b.purpose) && !b.file_name.empty() && std::filesystem::exists(b.directory / b.file_name, ec)) {
    ImGui::TextDisabled("%s exists and will be replaced.", b.file_name.c_str());
  } else {
    std::string exts;
    for (const std::string& e : browserExtensions(b.purpose)) exts += (exts.empty() ? "" : ", ") + e;
    ImGui::TextDisabled("Showing %s", b.show_all_files ? "all files" : exts.c_str());
  }
  // An error raised here (a file that cannot be written) opens over the browser, inside its popup: opened at the
  // top level it would close the browser, and the name typed with it.
  drawErrorDialog(state);
  ImGui::EndPopup();
}

}  // namespace vox::app
