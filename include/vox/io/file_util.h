#pragma once
// File helpers with honest errors. Saves are atomic: written to a temporary file in the same directory, flushed,
// then renamed over the target, so a failed save never damages the previous file.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "vox/core/result.h"

namespace vox::io {

// Whole file into memory. Errors: "<path>: no such file", "<path>: permission denied", ...
Result<std::vector<uint8_t>> readFileBytes(const std::filesystem::path& path);
// Atomic replace (temp file + fsync + rename). Errors name the path and the reason (e.g. "No space left on device").
Status writeFileAtomic(const std::filesystem::path& path, std::span<const uint8_t> bytes);
Status writeFileAtomic(const std::filesystem::path& path, const std::string& text);

}  // namespace vox::io
