// A .vxm file to .binvox without the grid in memory (vox/io/vxm_stream.h, convertVxmToBinvox). .vxm holds rows along
// x, layer after layer; binvox wants, for each x, each z, the column along y. Each pass over the .vxm file keeps
// the y columns of one block of x values for every layer (64 x 64 bit blocks transposed, as the in-memory encoder
// does), then emits that block's runs in binvox order; the runs merge across blocks, so the bytes are those of
// encodeBinvox.
#include <algorithm>

#include "io/binvox_detail.h"
#include "io/voxel_file_common.h"
#include "vox/io/file_util.h"
#include "vox/io/vxm_stream.h"

namespace vox::io {

namespace {

using binvox_detail::BinvoxRuns;
using binvox_detail::transpose64;
using voxel_file_detail::emitRuns;
using voxel_file_detail::Writer;

// The y columns of x values [xa, xb) (xa a multiple of 64) of every layer: column(x, z) is yw words.
struct ColumnBlock {
  int64_t xa = 0, xb = 0, yw = 0;
  int32_t nz = 0;
  std::vector<uint64_t> words;
  uint64_t* column(int64_t x, int32_t z) { return words.data() + ((x - xa) * nz + z) * yw; }
};

// Transposes the layers of one window into the block's columns.
void gatherColumns(const VxmWindow& win, ColumnBlock& block) {
  const VoxelGrid& g = win.grid;
  const int64_t wpr = g.wordsPerRow();
  uint64_t bits[64];
  for (int32_t z = win.core_begin; z < win.core_end; ++z) {
    const int32_t zl = z - win.z_offset;
    if (!g.layerAllocated(zl)) continue;
    const uint64_t* layer = g.layerWords(zl);
    for (int64_t bx = block.xa >> 6; bx * 64 < block.xb; ++bx) {
      for (int64_t yw = 0; yw < block.yw; ++yw) {
        for (int i = 0; i < 64; ++i) {
          const int64_t y = yw * 64 + i;
          if (y >= g.ny()) {
            bits[i] = 0;
            continue;
          }
          const uint64_t* row = layer + (y + 1) * wpr;  // unpadded word bx = padded bits 64 bx + 1 ..
          bits[i] = (row[bx] >> 1) | (bx + 1 < wpr ? row[bx + 1] << 63 : 0);
        }
        transpose64(bits);
        for (int i = 0; i < 64 && bx * 64 + i < block.xb; ++i) block.column(bx * 64 + i, z)[yw] = bits[i];
      }
    }
  }
}

}  // namespace

Status convertVxmToBinvox(const std::filesystem::path& vxm, const std::filesystem::path& binvox, uint64_t buffer_bytes,
                          int32_t window_layers) {
  auto header = readVxmHeader(vxm);
  if (!header) return header.error();
  const Dims dims = header->dims;
  const int64_t d = std::max({dims.nx, dims.ny, dims.nz});
  ColumnBlock block;
  block.yw = (int64_t(dims.ny) + 63) / 64;
  block.nz = dims.nz;
  const uint64_t per_x = uint64_t(dims.nz) * uint64_t(block.yw) * 8;
  const int64_t xs = std::max<int64_t>(64, int64_t(buffer_bytes / per_x) / 64 * 64);
  return writeFileAtomic(binvox, [&](ByteSink& sink) -> Status {
    Writer out(&sink);
    const std::string text = binvox_detail::binvoxHeader(dims, header->frame);
    out.bytes.assign(text.begin(), text.end());
    BinvoxRuns runs(out);
    for (int64_t xa = 0; xa < dims.nx; xa += xs) {
      block.xa = xa;
      block.xb = std::min<int64_t>(dims.nx, xa + xs);
      block.words.assign(size_t((block.xb - xa) * dims.nz * block.yw), 0);
      const Status read = readVxmInWindows(
          vxm, window_layers, 0,
          [&](const VxmWindow& win) {
            gatherColumns(win, block);
            return Status(Ok{});
          },
          xa == 0);
      if (!read) return read;
      for (int64_t x = xa; x < block.xb; ++x) {
        for (int32_t z = 0; z < d; ++z) {
          if (z >= dims.nz) {
            runs.add(false, uint64_t(d));  // padding to D^3
            continue;
          }
          emitRuns(block.column(x, z), dims.ny, runs);
          runs.add(false, uint64_t(d - dims.ny));
        }
      }
      if (!out.status().ok()) return out.status();
    }
    for (int64_t x = dims.nx; x < d; ++x) runs.add(false, uint64_t(d) * uint64_t(d));
    runs.flush();
    return out.flush();
  });
}

}  // namespace vox::io
