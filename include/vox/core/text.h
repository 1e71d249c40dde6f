#pragma once
// Small helpers every module writes messages with, kept in one place: byte sizes, grid dimensions, the machine's
// memory (for the limits the voxelizer, the file readers and the window enforce).
#include <cstdint>
#include <string>

#include "vox/core/voxel_grid.h"

namespace vox {

// "512 B", "3.5 KiB", "94.2 MiB", "1.29 GiB".
std::string formatBytes(uint64_t bytes);
// "1243 x 2110 x 4096".
std::string dimsText(const Dims& dims);
// Physical memory of this machine in bytes (0 if unknown).
uint64_t physicalMemoryBytes();

}  // namespace vox
