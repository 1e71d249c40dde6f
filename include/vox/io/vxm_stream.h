#pragma once
// .vxm files larger than memory (docs/file-format.md, "Streamed `.vxm` files"): written a slab of Z layers at a
// time, and read back a window of Z layers at a time, never holding the grid. The files are ordinary format-1
// `.vxm` files: loadVxm reads them, and the layer reader reads any `.vxm` file.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/file_util.h"

namespace vox::io {

// Encodes a .vxm file into `sink` layer by layer: the header goes out at once with its counts and CRC zeroed, the
// runs in chunks of about a megabyte as layers are appended (runs continue across appends), and finish() writes the
// completed header over the placeholder and the file CRC (of the header and the body, joined with zlib's
// crc32_combine). Memory: one chunk and one row, whatever the grid.
class VxmLayerWriter {
 public:
  VxmLayerWriter(ByteSink& sink, const Dims& dims, const GridFrame& frame);
  ~VxmLayerWriter();
  VxmLayerWriter(const VxmLayerWriter&) = delete;
  VxmLayerWriter& operator=(const VxmLayerWriter&) = delete;
  // Appends layers [z0, z1) of `layers` (a grid of dims.nx x dims.ny layers) as the grid's next layers.
  Status append(const VoxelGrid& layers, int32_t z0, int32_t z1);
  // Appends `layers` layers given as their runs (encodeVxmLayers, made elsewhere: another MPI rank) as the grid's
  // next layers: the file is the one append() of those layers would write. Runs that do not cover exactly the
  // layers' voxels are refused (kCorrupt).
  Status appendRuns(std::span<const uint8_t> runs, int32_t layers);
  // Once every layer of the grid is appended (refused otherwise).
  Status finish();
  uint64_t filled() const;
  uint64_t bodyBytes() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Layers [z0, z1) of `grid` encoded on their own as a .vxm body encodes them, for VxmLayerWriter::appendRuns: the
// runs of their voxels (x fastest, then y, then z), alternating empty and filled from an empty one (0 voxels when
// the first voxel is filled), as varints. About the size of those layers' part of the file's body.
std::vector<uint8_t> encodeVxmLayers(const VoxelGrid& grid, int32_t z0, int32_t z1);

// Writes a .vxm file atomically (writeFileAtomic) with `produce` appending its layers, lowest first.
Status saveVxmInSlabs(const std::filesystem::path& path, const Dims& dims, const GridFrame& frame,
                      const std::function<Status(VxmLayerWriter&)>& produce);

// A .vxm file's header, read and checked (magic, version, header CRC, dims, origin, voxel size) without the body.
struct VxmHeaderInfo {
  Dims dims;
  GridFrame frame;
  uint64_t filled = 0, runs = 0, body_bytes = 0;
};
Result<VxmHeaderInfo> readVxmHeader(const std::filesystem::path& path);

// A window of Z layers of a .vxm file: `grid` (the file's nx x ny and frame) holds the file's layers
// [z_offset, z_offset + grid.nz()); the layers [core_begin, core_end) are the ones this window stands for, and the
// window also holds up to `halo` layers on either side of them (fewer at the grid's ends).
struct VxmWindow {
  const VoxelGrid& grid;
  int32_t z_offset, core_begin, core_end;
};

// Reads a .vxm file window by window: checks it as loadVxm does (size, header CRC, then the file CRC, in a first
// pass over the file in chunks, so a damaged file is refused before any window), then decodes the runs, calling
// `visit` for consecutive cores of `layers` layers (the last may be shorter) with `halo` layers either side.
// The body's consistency (well-formed varints, runs covering the grid, the header's counts) is checked as the runs
// are decoded, with loadVxm's messages: a visitor may have seen windows before such an error is returned. Memory:
// one window, a chunk of the file, and the 2 x halo layers copied from one window to the next.
// `check_crc` false skips the file CRC (for a further pass over a file already checked).
Status readVxmInWindows(const std::filesystem::path& path, int32_t layers, int32_t halo,
                        const std::function<Status(const VxmWindow&)>& visit, bool check_crc = true);

// A .vxm file converted to .binvox (written atomically, the bytes saveBinvox writes for the grid) without holding
// the grid: binvox runs over x, then z, then y, so the file is read once per block of x values whose y columns of
// every layer fit in `buffer_bytes` (blocks of 64 x values at least), in windows of `window_layers` layers.
// Time: the passes, each decoding the whole .vxm body; memory: the block, one window.
Status convertVxmToBinvox(const std::filesystem::path& vxm, const std::filesystem::path& binvox, uint64_t buffer_bytes,
                          int32_t window_layers);

// A coarse copy of a .vxm file's grid, for looking at a grid too large for memory (the window opens such a file so):
// each block of level x level x level voxels becomes one voxel, filled when any of its voxels is (so walls thinner
// than a block stay visible), dims ceil(n / level), voxel size level x h, the same origin, units and source. Read in
// windows of `level` layers; memory: the coarse grid, one window, and one row of words per coarse row.
// Fails with the reader's errors, or kCancelled when `progress` says so.
Result<VoxelGrid> readVxmCoarse(const std::filesystem::path& path, int32_t level, const ProgressFn& progress = {});
// The smallest power of two level (1, 2, 4, ..., 64) whose coarse grid of a grid of these dims takes at most
// `bytes` (estimateGridBytes); 64 when none does.
int32_t coarseLevelFor(const Dims& dims, uint64_t bytes);

// Layers of a grid of these dims that fit in `bytes` (at least 1): for choosing window sizes.
int32_t layersWithin(const Dims& dims, uint64_t bytes);

}  // namespace vox::io
