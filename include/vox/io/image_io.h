#pragma once
// PNG and CSV export (PNG through stb_image_write from Debian's libstb). Saves are atomic.
#include <filesystem>
#include <string_view>
#include <vector>

#include "vox/core/image.h"
#include "vox/core/result.h"

namespace vox::io {

Status savePng(const ImageRgb& image, const std::filesystem::path& path);
Status savePng(const ImageRgba& image, const std::filesystem::path& path);
// The PNG bytes, for writing together with other files (writeFilesAtomic); `path` is named in errors.
Result<std::vector<uint8_t>> encodePng(const ImageRgb& image, const std::filesystem::path& path);
Result<std::vector<uint8_t>> encodePng(const ImageRgba& image, const std::filesystem::path& path);
// Reads a PNG (for tests and image baselines) as RGBA.
Result<ImageRgba> loadPng(const std::filesystem::path& path);

}  // namespace vox::io
