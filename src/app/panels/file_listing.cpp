// The file browser's listing (file_browser.cpp draws the dialog): reading a directory into its folders and matching
// files, and the widgets that move through it (Up, Home, the path field, the list of entries).
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

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

bool matchesExtension(const std::string& name, const std::vector<std::string>& extensions) {
  const std::string l = lower(name);
  return std::any_of(extensions.begin(), extensions.end(), [&](const std::string& e) {
    return l.size() > e.size() && l.compare(l.size() - e.size(), e.size(), e) == 0;
  });
}

void listDirectory(FileBrowser& b) {
  b.entries.clear();
  b.error.clear();
  b.listed_directory = b.directory;
  b.listed_all_files = b.show_all_files;
  b.needs_listing = false;
  const std::vector<std::string>& ext = b.extensions;
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
    if (!dir && !b.show_all_files && !matchesExtension(name, ext)) continue;
    FileBrowser::Entry entry{name, dir, 0};
    if (!dir) entry.size = it->file_size(e2);
    b.entries.push_back(std::move(entry));
  }
  std::sort(b.entries.begin(), b.entries.end(), [](const FileBrowser::Entry& x, const FileBrowser::Entry& y) {
    if (x.is_directory != y.is_directory) return x.is_directory;
    return lower(x.name) < lower(y.name);
  });
}

void drawBrowserNavigation(FileBrowser& b) {
  if (widget::Button("Up")) {
    b.directory = b.directory.parent_path();
    b.needs_listing = true;
  }
  ImGui::SameLine();
  if (widget::Button("Home")) {
    if (const char* home = std::getenv("HOME")) b.directory = home;
    b.needs_listing = true;
  }
  ImGui::SameLine();
  std::string dir_text = b.directory.string();
  ImGui::SetNextItemWidth(-1.0f);
  if (widget::InputText("##dir", &dir_text, ImGuiInputTextFlags_EnterReturnsTrue)) {
    b.directory = dir_text;
    b.needs_listing = true;
  }
}

bool drawBrowserEntries(FileBrowser& b, float footer) {
  bool activate = false;
  if (ImGui::BeginChild("##entries", ImVec2(0.0f, -footer), true)) {
    if (!b.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", b.error.c_str());
    for (const FileBrowser::Entry& e : b.entries) {
      const std::string label = e.is_directory ? "[dir]  " + e.name + "/" : "       " + e.name;
      const bool selected = !e.is_directory && e.name == b.file_name;
      if (widget::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
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
  return activate;
}

}  // namespace vox::app
