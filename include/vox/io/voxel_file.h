#pragma once
// Voxel files: .vxm (voxmod's own run-length format, docs/file-format.md) and .binvox (docs/conventions.md, ".binvox").
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::io {

// .vxm: magic, version, dims, origin, voxel size, units, source name, run-length body (runs alternate empty and
// filled, starting with empty), CRC-32 over everything. Newer versions, bad magic, truncation and CRC mismatches
// are refused with a message saying which.
inline constexpr uint32_t kVxmVersion = 1;
std::vector<uint8_t> encodeVxm(const VoxelGrid& grid);
// memory_limit_bytes: refuse (kLimit) a file whose grid would need more; 0 means the machine's physical memory.
Result<VoxelGrid> decodeVxm(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit_bytes = 0);
Status saveVxm(const VoxelGrid& grid, const std::filesystem::path& path);
Result<VoxelGrid> loadVxm(const std::filesystem::path& path);

// .binvox: the grid padded to D^3 with D = the largest dim, translate = origin, scale = D * voxel_size.
// Reading gives a D^3 grid (the file does not record the unpadded dims) with origin = translate and
// voxel_size = scale / D. Files without translate/scale lines (some writers) read with origin 0, scale 1.
// A non-cubic "dim d w h" reads as nx = d, ny = w, nz = h (binvox's read_binvox.cc), voxel_size = scale / max.
// Only "#binvox 1" is read. frame.source is the file name.
std::vector<uint8_t> encodeBinvox(const VoxelGrid& grid);
Result<VoxelGrid> decodeBinvox(std::span<const uint8_t> bytes, const std::string& name,
                               uint64_t memory_limit_bytes = 0);
Status saveBinvox(const VoxelGrid& grid, const std::filesystem::path& path);
Result<VoxelGrid> loadBinvox(const std::filesystem::path& path);

// By extension (.vxm, .binvox; case-insensitive). Unknown extensions are an error naming the supported ones.
bool isVoxelFile(const std::filesystem::path& path);
Result<VoxelGrid> loadVoxelFile(const std::filesystem::path& path);
Status saveVoxelFile(const VoxelGrid& grid, const std::filesystem::path& path);

// Several grids as voxel files (each format by its path's extension), written as one: the directories are created,
// every file is encoded and written under a temporary name, and only when all are complete are they renamed over
// their targets (writeFilesAtomic), so a failure leaves every target as it was. An unknown extension is refused
// before anything is written.
struct VoxelFileToWrite {
  std::filesystem::path path;
  VoxelGrid grid;
};
Status saveVoxelFiles(std::span<const VoxelFileToWrite> files);

}  // namespace vox::io
