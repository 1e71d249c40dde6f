// Voxel files: voxmod's .vxm (vxm.cpp) and the .binvox interchange format (binvox.cpp), chosen by file extension.
// What the two codecs share is voxel_file_common.cpp.
#include "vox/io/voxel_file.h"

#include <zlib.h>

#include <algorithm>
#include <system_error>

#include "io/voxel_file_common.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::io {

// ---- Dispatch by extension ----

namespace {

enum class VoxelFormat { kUnknown, kVxm, kBinvox };

VoxelFormat formatOf(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".vxm") return VoxelFormat::kVxm;
  if (ext == ".binvox") return VoxelFormat::kBinvox;
  return VoxelFormat::kUnknown;
}

Error unknownFormat(const std::filesystem::path& path) {
  return makeError(ErrorCode::kUnsupported, path.string() + ": unknown voxel file type '" + path.extension().string() +
                                                "' (supported: .vxm, .binvox)");
}

}  // namespace

bool isVoxelFile(const std::filesystem::path& path) { return formatOf(path) != VoxelFormat::kUnknown; }

Result<VoxelGrid> loadVoxelFile(const std::filesystem::path& path) {
  switch (formatOf(path)) {
    case VoxelFormat::kVxm:
      return loadVxm(path);
    case VoxelFormat::kBinvox:
      return loadBinvox(path);
    case VoxelFormat::kUnknown:
      break;
  }
  return unknownFormat(path);
}

Status saveVoxelFile(const VoxelGrid& grid, const std::filesystem::path& path) {
  switch (formatOf(path)) {
    case VoxelFormat::kVxm:
      return saveVxm(grid, path);
    case VoxelFormat::kBinvox:
      return saveBinvox(grid, path);
    case VoxelFormat::kUnknown:
      break;
  }
  return unknownFormat(path);
}

Status saveVoxelFiles(std::span<const VoxelFileToWrite> files) {
  for (const VoxelFileToWrite& f : files) {
    if (formatOf(f.path) == VoxelFormat::kUnknown) return unknownFormat(f.path);
  }
  for (const VoxelFileToWrite& f : files) {
    const std::filesystem::path dir = f.path.parent_path();
    if (dir.empty()) continue;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return makeError(ErrorCode::kIo, dir.string() + ": cannot create the directory: " + ec.message());
  }
  std::vector<PendingFile> pending;
  pending.reserve(files.size());
  for (const VoxelFileToWrite& f : files) {
    pending.push_back(
        PendingFile{f.path, formatOf(f.path) == VoxelFormat::kVxm ? encodeVxm(f.grid) : encodeBinvox(f.grid)});
  }
  return writeFilesAtomic(pending);
}

}  // namespace vox::io
