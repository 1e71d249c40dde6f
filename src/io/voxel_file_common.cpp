// What the two voxel file codecs share (voxel_file_common.h): the memory check before a decoder allocates, the
// CRC-32 they keep, and a grid encoded into memory.
#include "io/voxel_file_common.h"

#include <zlib.h>

#include <algorithm>

#include "vox/core/text.h"

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

}  // namespace vox::io
