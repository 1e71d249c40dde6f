#pragma once
// The window's own file browser (panels/file_browser.cpp, file_browsing.h): where it is, what it lists and the action
// the chosen path is given to.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vox::app {

struct AppState;
enum class ActionId;

struct FileBrowser {
  struct Entry {
    std::string name;
    bool is_directory = false;
    uintmax_t size = 0;
  };
  bool open_requested = false;
  bool accepted = false;  // the file chosen went through (between frames): the browser closes
  // What it is for: the action its path is given to (one of the table's that takes a path), its title, the extensions
  // it lists (none: it names a folder), and whether it names a file to write (the first extension added to a name
  // without one) or one to open.
  ActionId action{};
  std::string title;
  std::vector<std::string> extensions;
  bool saving = false;
  bool went_through = false;  // the path last given to a path action was used (usePath): the browser may close
  std::filesystem::path directory;
  std::string file_name;  // typed or clicked
  bool show_all_files = false;
  std::string error;  // e.g. the directory could not be listed
  // The listing of `directory`, refreshed when the directory or the filter changes (not every frame).
  std::vector<Entry> entries;
  std::filesystem::path listed_directory;
  bool listed_all_files = false;
  bool needs_listing = true;
  // Run after a successful save from the browser (the unsaved-changes prompt's "Save" continues with it).
  std::function<void(AppState&)> then;
};

}  // namespace vox::app
