#pragma once
// What the window remembers between runs: size, recent files and the user's choices. Stored as "key = value" lines
// in <config dir>/voxmod.ini beside ImGui's own imgui.ini. The config directory is $XDG_CONFIG_HOME/voxmod, or
// ~/.config/voxmod when XDG_CONFIG_HOME is unset (XDG Base Directory specification).
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "vox/core/result.h"

namespace vox::app {

inline constexpr size_t kMaxRecentFiles = 10;
inline constexpr size_t kMaxFileUnits = 200;

struct Settings {
  int window_width = 1280;
  int window_height = 800;
  std::vector<std::string> recent_files;  // most recent first, absolute paths
  std::string last_directory;             // where the file browser opens
  int64_t resolution = 200;               // the voxelize dialog's last choice
  std::string fill_mode = "auto";
  bool lit = true;  // shading table: lit (true) or the thesis's classic table
  bool round_points = false;
  float point_size_px = 0.0f;  // fixed point diameter; 0: the closed-surface size (automatic)
  bool lod = true;             // coarser points while the view moves
  // The units the user gave files that name none (STL, OBJ, PLY, OFF, .binvox): (absolute path, units), most recent
  // first, at most kMaxFileUnits.
  std::vector<std::pair<std::string, std::string>> file_units;
};

// Empty when neither XDG_CONFIG_HOME nor HOME is set (the window then remembers nothing).
std::filesystem::path configDirectory();

// Unknown keys and malformed lines are ignored (an old or hand-edited file must not stop the window from opening);
// a missing file gives the defaults.
Settings loadSettings(const std::filesystem::path& file);
std::string formatSettings(const Settings& settings);
// Creates the directory when needed; saves atomically.
Status saveSettings(const Settings& settings, const std::filesystem::path& file);

// Remembers the units the user gave a file that names none (absolute path); "model" forgets them.
void rememberFileUnits(Settings& settings, const std::string& path, const std::string& units);
// The units remembered for that file; "model" (none) when the user never gave it any.
std::string rememberedFileUnits(const Settings& settings, const std::string& path);

// Puts `path` first in the recent list, removing duplicates and keeping at most kMaxRecentFiles.
void addRecentFile(Settings& settings, const std::string& path);

}  // namespace vox::app
