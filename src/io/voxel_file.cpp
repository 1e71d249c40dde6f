// Voxel files: voxmod's .vxm (vxm.cpp) and the .binvox interchange format (binvox.cpp). This file holds what the
// two codecs share (declared in voxel_file_common.h) and the choice of format by file extension.
#include "vox/io/voxel_file.h"

#include <zlib.h>

#include <algorithm>
#include <system_error>

#include "io/voxel_file_common.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::io {

namespace voxel_file_detail {

// Memory for `layers` allocated Z layers of a grid with dims d, compared with the machine's memory.
// `extra` is working memory the decoder needs besides the grid.
Status checkLayerMemory(const Dims& d, int64_t layers, const std::string& name, uint64_t limit, uint64_t extra) {
  const Dims one{d.nx, d.ny, 1};
  const uint64_t layer_bytes = estimateGridBytes(one) - estimateGridBytes(Dims{d.nx, d.ny, 0});
  const uint64_t need = layer_bytes * uint64_t(layers + 1) + extra;  // + the shared zero layer
  const uint64_t have = limit > 0 ? limit : physicalMemoryBytes();   // 0: unknown, no limit
  if (have > 0 && need > have) {
    return makeError(ErrorCode::kLimit, name + ": grid " + dimsText(d) + " with " + std::to_string(layers) +
                                            " occupied layers needs " + formatBytes(need) +
                                            " of memory; the limit is " + formatBytes(have));
  }
  return Ok{};
}

// CRC-32 of n bytes, continuing from `crc` (the CRC of the bytes before them; 0 to start).
uint32_t crc32Of(const uint8_t* data, size_t n, uint32_t crc_before) {
  // zlib's crc32 takes a uInt length: feed large buffers in pieces.
  uLong crc = crc_before;
  while (n > 0) {
    const size_t piece = std::min<size_t>(n, 1u << 30);
    crc = ::crc32(crc, data, uInt(piece));
    data += piece;
    n -= piece;
  }
  return uint32_t(crc);
}

// A streaming encoder's output collected in memory (a memory sink does not fail).
std::vector<uint8_t> encodeToMemory(Status (*encode)(const VoxelGrid&, ByteSink&), const VoxelGrid& grid) {
  VectorSink sink;
  (void)encode(grid, sink);
  return std::move(sink.bytes);
}

}  // namespace voxel_file_detail

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
