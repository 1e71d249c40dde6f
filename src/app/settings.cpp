#include "app/settings.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include "vox/core/units.h"
#include "vox/io/file_util.h"
#include "vox/core/text.h"

namespace vox::app {
namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

void parseBool(const std::string& text, bool& out) {
  if (text == "1" || text == "true") out = true;
  if (text == "0" || text == "false") out = false;
}

}  // namespace

std::filesystem::path configDirectory() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "voxmod";
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "voxmod";
  }
  return {};
}

Settings loadSettings(const std::filesystem::path& file) {
  Settings s;
  std::ifstream in(file);
  if (!in) return s;
  std::vector<std::string> recent;
  std::string line;
  while (std::getline(in, line)) {
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    const size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = trim(line.substr(0, eq));
    const std::string value = trim(line.substr(eq + 1));
    if (key == "window_width")
      parseNumber(value, s.window_width);
    else if (key == "window_height")
      parseNumber(value, s.window_height);
    else if (key == "recent")
      recent.push_back(value);
    else if (key == "file_units" && value.find(' ') != std::string::npos && s.file_units.size() < kMaxFileUnits &&
             metresPerUnit(value.substr(0, value.find(' '))) > 0.0)  // a unit voxmod knows, or nothing
      s.file_units.emplace_back(trim(value.substr(value.find(' ') + 1)), value.substr(0, value.find(' ')));
    else if (key == "last_directory")
      s.last_directory = value;
    else if (key == "resolution")
      parseNumber(value, s.resolution);
    else if (key == "fill_mode")
      s.fill_mode = value;
    else if (key == "lit")
      parseBool(value, s.lit);
    else if (key == "round_points")
      parseBool(value, s.round_points);
    else if (key == "point_size_px")
      parseNumber(value, s.point_size_px);
    else if (key == "lod")
      parseBool(value, s.lod);
  }
  // Values from a hand-edited file are clamped to what the window can use.
  s.window_width = std::clamp(s.window_width, 640, 16384);
  s.window_height = std::clamp(s.window_height, 480, 16384);
  s.resolution = std::clamp<int64_t>(s.resolution, 1, 4096);
  s.point_size_px = std::clamp(s.point_size_px, 0.0f, 32.0f);
  for (const std::string& r : recent) {
    if (s.recent_files.size() < kMaxRecentFiles) s.recent_files.push_back(r);
  }
  return s;
}

std::string formatSettings(const Settings& s) {
  std::ostringstream out;
  out << "# voxmod settings, rewritten when the window closes\n";
  out << "window_width = " << s.window_width << "\n";
  out << "window_height = " << s.window_height << "\n";
  for (const std::string& r : s.recent_files) out << "recent = " << r << "\n";
  out << "last_directory = " << s.last_directory << "\n";
  out << "resolution = " << s.resolution << "\n";
  out << "fill_mode = " << s.fill_mode << "\n";
  out << "lit = " << (s.lit ? 1 : 0) << "\n";
  out << "round_points = " << (s.round_points ? 1 : 0) << "\n";
  out << "point_size_px = " << s.point_size_px << "\n";
  out << "lod = " << (s.lod ? 1 : 0) << "\n";
  for (const auto& [path, units] : s.file_units) out << "file_units = " << units << " " << path << "\n";
  return out.str();
}

Status saveSettings(const Settings& settings, const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) return makeError(ErrorCode::kIo, file.parent_path().string() + ": " + ec.message());
  return io::writeFileAtomic(file, formatSettings(settings));
}

void rememberFileUnits(Settings& settings, const std::string& path, const std::string& units) {
  auto& f = settings.file_units;
  std::erase_if(f, [&](const auto& e) { return e.first == path; });
  // Only what one line of the file holds and gives back: a known unit, a path without line breaks or spaces at its end.
  if (metresPerUnit(units) <= 0.0 || path.empty() || path.find_first_of("\n\r") != std::string::npos ||
      std::isspace(static_cast<unsigned char>(path.back()))) {
    return;
  }
  f.insert(f.begin(), {path, units});
  if (f.size() > kMaxFileUnits) f.resize(kMaxFileUnits);
}

std::string rememberedFileUnits(const Settings& settings, const std::string& path) {
  for (const auto& [p, units] : settings.file_units) {
    if (p == path) return units;
  }
  return "model";
}

void addRecentFile(Settings& settings, const std::string& path) {
  auto& r = settings.recent_files;
  std::erase(r, path);
  r.insert(r.begin(), path);
  if (r.size() > kMaxRecentFiles) r.resize(kMaxRecentFiles);
}

}  // namespace vox::app
