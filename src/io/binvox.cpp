// .binvox: Patrick Min's voxel format (https://www.patrickmin.com/binvox/binvox.html) and docs/conventions.md,
// ".binvox": ASCII header, then (value, count) byte pairs over the order y fastest, then z, then x.
//
// The grid stores rows along x and binvox wants columns along y: 64 x 64 bit blocks are transposed both ways, so
// runs are still found one countr_zero per run (voxel_file_common.h).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "io/binvox_detail.h"
#include "io/voxel_file_common.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/voxel_file.h"

namespace vox::io {

namespace {

using voxel_file_detail::checkLayerMemory;
using voxel_file_detail::emitRuns;
using voxel_file_detail::encodeToMemory;
using voxel_file_detail::Writer;
using namespace binvox_detail;

std::string baseName(const std::string& name) { return std::filesystem::path(name).filename().string(); }

// y-columns of up to 64 consecutive x values, for the Z layers that hold voxels (numbered compactly, so empty
// layers cost nothing): column(xi, z) is yWords() words, bit y of the column = voxel (x0 + xi, y, z).
class ColumnBlocks {
 public:
  template <class LayerUsed>
  ColumnBlocks(const Dims& dims, LayerUsed used) : y_words_((int64_t(dims.ny) + 63) / 64) {
    width_ = std::min<int64_t>(64, dims.nx);
    slots_.assign(size_t(dims.nz), -1);
    for (int32_t z = 0; z < dims.nz; ++z) {
      if (used(z)) slots_[size_t(z)] = count_++;
    }
    words_.assign(size_t(width_ * count_ * y_words_), 0);
  }
  // Bytes the buffer would take, for memory checks before it is built.
  static uint64_t bytesFor(const Dims& dims, int64_t layers) {
    return uint64_t(std::min<int64_t>(64, dims.nx)) * uint64_t(layers) * uint64_t((int64_t(dims.ny) + 63) / 64) * 8;
  }
  int32_t slot(int32_t z) const { return slots_[size_t(z)]; }
  int64_t yWords() const { return y_words_; }
  int64_t blockWidth() const { return width_; }
  uint64_t* column(int64_t xi, int32_t z) { return words_.data() + (xi * count_ + slots_[size_t(z)]) * y_words_; }
  void clear() { std::fill(words_.begin(), words_.end(), 0); }

 private:
  int64_t y_words_;
  int64_t width_ = 0;
  int32_t count_ = 0;
  std::vector<int32_t> slots_;
  std::vector<uint64_t> words_;
};

// The binvox encoder, streamed in chunks of about a megabyte (binvox has no checksum or counts to patch).
Status encodeBinvoxTo(const VoxelGrid& grid, ByteSink& sink) {
  const int32_t d = std::max({grid.nx(), grid.ny(), grid.nz()});
  const std::string header = binvoxHeader(grid.dims(), grid.frame());
  Writer out(&sink);
  out.bytes.assign(header.begin(), header.end());
  if (d == 0) return out.flush();
  BinvoxRuns runs(out);
  // Binvox wants columns along y; the grid stores rows along x. Blocks of 64 x 64 bits are transposed into a
  // buffer of y-columns for 64 consecutive x and every allocated layer, which is then emitted as runs in the
  // file's order (x, then z, then y), one countr_zero per run.
  ColumnBlocks cols(grid.dims(), [&](int32_t z) { return grid.layerAllocated(z); });
  const int64_t wpr = grid.wordsPerRow();
  uint64_t block[64];
  for (int64_t x0 = 0; x0 < d && out.status().ok(); x0 += 64) {
    const int64_t bx = x0 >> 6;
    if (x0 < grid.nx()) {
      for (int32_t z = 0; z < grid.nz(); ++z) {
        if (cols.slot(z) < 0) continue;
        const uint64_t* layer = grid.layerWords(z);
        for (int64_t yw = 0; yw < cols.yWords(); ++yw) {
          for (int i = 0; i < 64; ++i) {
            const int64_t y = yw * 64 + i;
            if (y >= grid.ny()) {
              block[i] = 0;
              continue;
            }
            const uint64_t* row = layer + (y + 1) * wpr;  // unpadded word bx = padded bits 64 bx + 1 ..
            block[i] = (row[bx] >> 1) | (bx + 1 < wpr ? row[bx + 1] << 63 : 0);
          }
          transpose64(block);
          for (int64_t xi = 0; xi < cols.blockWidth(); ++xi) cols.column(xi, z)[yw] = block[xi];
        }
      }
    }
    for (int64_t x = x0; x < std::min<int64_t>(x0 + 64, d); ++x) {
      for (int32_t z = 0; z < d; ++z) {
        if (x >= grid.nx() || z >= grid.nz() || cols.slot(z) < 0) {
          runs.add(false, uint64_t(d));  // padding to D^3, or an empty layer
          continue;
        }
        emitRuns(cols.column(x - x0, z), grid.ny(), runs);
        runs.add(false, uint64_t(d - grid.ny()));
      }
    }
  }
  runs.flush();
  return out.flush();
}

// The ASCII header, up to and including its "data" line.
struct BinvoxHeader {
  Dims dims;
  glm::dvec3 translate;
  double scale = 1.0;
  size_t data_at = 0;  // offset of the first (value, count) pair
};

Result<BinvoxHeader> parseBinvoxHeader(std::span<const uint8_t> bytes, const std::string& name) {
  const char* text = reinterpret_cast<const char*>(bytes.data());
  const size_t size = bytes.size();
  size_t pos = 0;
  int line_no = 0;
  auto nextLine = [&](std::string_view& line) {
    if (pos >= size) return false;
    const void* nl = std::memchr(text + pos, '\n', size - pos);
    const size_t end = nl ? size_t(static_cast<const char*>(nl) - text) : size;
    line = std::string_view(text + pos, end - pos);
    pos = nl ? end + 1 : size;
    ++line_no;
    return true;
  };
  auto error = [&](ErrorCode code, const std::string& what) {
    return makeError(code, name + ":" + std::to_string(line_no) + ": " + what);
  };

  std::string_view line;
  if (!nextLine(line) || line.substr(0, 7) != "#binvox") {
    return makeError(ErrorCode::kParse, name + ": not a binvox file (it does not start with '#binvox')");
  }
  {
    const auto words = splitWords(line.substr(7));
    int64_t version = 0;
    if (words.size() != 1 || !parseNumber(words[0], version)) return error(ErrorCode::kParse, "bad '#binvox' line");
    if (version != 1) {
      return error(ErrorCode::kUnsupported,
                   "binvox version " + std::to_string(version) + " is not supported (this build reads version 1)");
    }
  }
  // Header lines in any order until "data". Writers differ: binvox writes dim, translate, scale; some writers
  // (cuda_voxelizer, older trimesh) leave out translate and scale, which then default to 0 and 1.
  Dims dims{-1, -1, -1};
  glm::dvec3 translate(0.0);
  double scale = 1.0;
  bool have_dim = false, have_data = false;
  while (nextLine(line)) {
    const auto words = splitWords(line);
    if (words.empty()) continue;
    if (words[0] == "data") {
      have_data = true;
      break;
    }
    if (words[0] == "dim") {
      int64_t v[3];
      if (words.size() != 4 || !parseNumber(words[1], v[0]) || !parseNumber(words[2], v[1]) ||
          !parseNumber(words[3], v[2])) {
        return error(ErrorCode::kParse, "expected 'dim D D D'");
      }
      for (int64_t& x : v) {
        if (x < 1 || x > VoxelGrid::kMaxDim) {
          return error(ErrorCode::kLimit,
                       "dimension " + std::to_string(x) + " is outside 1.." + std::to_string(VoxelGrid::kMaxDim));
        }
      }
      // "dim depth width height" (binvox's read_binvox.cc): x has depth voxels, y width, z height, and the
      // index is x * width * height + z * width + y.
      dims = {int32_t(v[0]), int32_t(v[1]), int32_t(v[2])};
      have_dim = true;
    } else if (words[0] == "translate") {
      if (words.size() != 4 || !parseFileNumber(words[1], translate.x) || !parseFileNumber(words[2], translate.y) ||
          !parseFileNumber(words[3], translate.z)) {
        return error(ErrorCode::kParse, "expected 'translate x y z' with three finite numbers");
      }
    } else if (words[0] == "scale") {
      if (words.size() != 2 || !parseFileNumber(words[1], scale) || !(scale > 0)) {
        return error(ErrorCode::kParse, "expected 'scale s' with a positive number");
      }
    } else {
      return error(ErrorCode::kParse, "unknown binvox header line " + quoteBytes(line));
    }
  }
  if (!have_data) return makeError(ErrorCode::kParse, name + ": binvox header has no 'data' line");
  if (!have_dim) return makeError(ErrorCode::kParse, name + ": binvox header has no 'dim' line");
  return BinvoxHeader{dims, translate, scale, pos};
}

// Pass 1: the runs must cover exactly D^3 voxels with values 0/1; note the Z layers that filled voxels touch.
Result<std::vector<uint8_t>> binvoxLayersUsed(std::span<const uint8_t> bytes, const BinvoxHeader& h,
                                              const std::string& name, uint64_t memory_limit_bytes) {
  const Dims& dims = h.dims;
  const size_t pos = h.data_at;
  const size_t size = bytes.size();
  const uint64_t total = uint64_t(dims.count());
  const uint64_t width = uint64_t(dims.ny), height = uint64_t(dims.nz);
  const uint8_t* data = bytes.data() + pos;
  const size_t data_bytes = size - pos;
  const size_t pairs = data_bytes / 2;
  auto dataError = [&](ErrorCode code, const std::string& what) {
    return makeError(code, name + ": binvox data " + what);
  };
  std::vector<uint8_t> layer_used(size_t(dims.nz), 0);
  uint64_t covered = 0;
  for (size_t i = 0; i < pairs; ++i) {
    const uint8_t v = data[2 * i], n = data[2 * i + 1];
    if (v > 1) {
      return dataError(ErrorCode::kParse, "has value " + std::to_string(v) + " at byte " + std::to_string(pos + 2 * i) +
                                              " (values are 0 or 1)");
    }
    if (n == 0) {
      return dataError(ErrorCode::kParse, "has a run of length 0 at byte " + std::to_string(pos + 2 * i + 1) +
                                              " (run lengths are 1..255)");
    }
    if (n > total - covered) {
      return dataError(ErrorCode::kParse, "runs past the " + std::to_string(total) + " voxels of the grid (at byte " +
                                              std::to_string(pos + 2 * i) + ")");
    }
    if (v == 1) {
      // Consecutive voxels share (x, z) for up to `width` voxels; a run of at most 255 touches few z values.
      for (uint64_t k = covered; k < covered + n; k += width - (k % width)) {
        layer_used[size_t((k / width) % height)] = 1;
      }
    }
    covered += n;
  }
  if (covered != total || data_bytes % 2 != 0) {
    return dataError(ErrorCode::kParse, "is truncated: the runs cover " + std::to_string(covered) + " of " +
                                            std::to_string(total) + " voxels" +
                                            (data_bytes % 2 ? " and end with half a pair" : ""));
  }
  const int64_t layers = std::count(layer_used.begin(), layer_used.end(), uint8_t(1));
  if (Status s = checkLayerMemory(dims, layers, name, memory_limit_bytes, ColumnBlocks::bytesFor(dims, layers));
      !s.ok()) {
    return s.error();
  }
  return layer_used;
}

// Pass 2: the runs of 64 consecutive x values (a block of the file) are set into y-columns with word masks,
// then 64 x 64 bit blocks are transposed into the grid's x-rows: the reverse of encodeBinvox.
void fillBinvoxGrid(VoxelGrid& grid, std::span<const uint8_t> bytes, const BinvoxHeader& h,
                    const std::vector<uint8_t>& layer_used) {
  const Dims& dims = h.dims;
  const uint64_t width = uint64_t(dims.ny), height = uint64_t(dims.nz);
  const uint8_t* data = bytes.data() + h.data_at;
  const size_t pairs = (bytes.size() - h.data_at) / 2;
  ColumnBlocks cols(dims, [&](int32_t z) { return layer_used[size_t(z)] != 0; });
  const int64_t wpr = grid.wordsPerRow();
  int64_t block_x0 = -1;  // first x of the block in the buffer; -1 while the buffer is empty
  uint64_t block[64];
  auto flushBlock = [&]() {
    if (block_x0 < 0) return;
    const int64_t bx = block_x0 >> 6;
    for (int32_t z = 0; z < dims.nz; ++z) {
      if (cols.slot(z) < 0) continue;
      uint64_t* layer = grid.mutableLayerWords(z);
      for (int64_t yw = 0; yw < cols.yWords(); ++yw) {
        for (int64_t xi = 0; xi < 64; ++xi) block[xi] = xi < cols.blockWidth() ? cols.column(xi, z)[yw] : 0;
        transpose64(block);
        for (int64_t i = 0; i < 64 && yw * 64 + i < dims.ny; ++i) {
          if (block[i] == 0) continue;
          uint64_t* row = layer + (yw * 64 + i + 1) * wpr;  // voxel x = padded bit x + 1
          row[bx] |= block[i] << 1;
          if (bx + 1 < wpr) row[bx + 1] |= block[i] >> 63;
        }
      }
    }
    cols.clear();
    block_x0 = -1;
  };
  uint64_t k = 0;
  for (size_t i = 0; i < pairs; ++i) {
    uint64_t n = data[2 * i + 1];
    if (data[2 * i] == 0) {
      k += n;
      continue;
    }
    while (n > 0) {
      const uint64_t y0 = k % width;
      const uint64_t col = k / width;  // x * height + z
      const int32_t z = int32_t(col % height);
      const int64_t x = int64_t(col / height);
      const uint64_t len = std::min<uint64_t>(n, width - y0);
      if (block_x0 >= 0 && (x >> 6) != (block_x0 >> 6)) flushBlock();
      block_x0 = x & ~int64_t(63);
      // Bits y0 .. y0 + len - 1 of the column: at most 255 bits, so a few words.
      uint64_t* c = cols.column(x - block_x0, z);
      for (uint64_t y = y0; y < y0 + len;) {
        const uint64_t w = y >> 6, b = y & 63;
        const uint64_t take = std::min<uint64_t>(64 - b, y0 + len - y);
        c[w] |= (take == 64 ? ~uint64_t(0) : ((uint64_t(1) << take) - 1)) << b;
        y += take;
      }
      k += len;
      n -= len;
    }
  }
  flushBlock();
}

}  // namespace

std::vector<uint8_t> encodeBinvox(const VoxelGrid& grid) { return encodeToMemory(encodeBinvoxTo, grid); }

Result<VoxelGrid> decodeBinvox(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit_bytes) {
  auto header = parseBinvoxHeader(bytes, name);
  if (!header.ok()) return header.error();
  const BinvoxHeader& h = header.value();
  auto layer_used = binvoxLayersUsed(bytes, h, name, memory_limit_bytes);
  if (!layer_used.ok()) return layer_used.error();

  GridFrame frame;
  frame.origin = h.translate;
  // The file stores the edge of the cube the grid was fitted into (docs/conventions.md, ".binvox"): voxel size =
  // scale / D, with D the largest dimension when a file is not cubic.
  frame.voxel_size = h.scale / double(std::max({h.dims.nx, h.dims.ny, h.dims.nz}));
  frame.source = baseName(name);
  VoxelGrid grid(h.dims, frame);
  fillBinvoxGrid(grid, bytes, h, layer_used.value());
  return grid;
}

Status saveBinvox(const VoxelGrid& grid, const std::filesystem::path& path) {
  if (grid.empty()) return makeError(ErrorCode::kInvalidArgument, path.string() + ": cannot save an empty grid");
  return writeFileAtomic(path, [&](ByteSink& sink) { return encodeBinvoxTo(grid, sink); });
}

Result<VoxelGrid> loadBinvox(const std::filesystem::path& path) {
  auto bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.error();
  return decodeBinvox(bytes.value(), path.string());
}

namespace binvox_detail {

// Transposes a 64 x 64 bit matrix in place: afterwards bit c of a[r] is what bit r of a[c] was. The recursive
// block swap of Hacker's Delight (H. S. Warren, 2nd ed., section 7-3), for 64-bit words, least significant bit
// first: swap the off-diagonal 32 x 32 blocks, then the 16 x 16 blocks inside each, and so on.
void transpose64(uint64_t* a) {
  uint64_t m = 0x00000000FFFFFFFFull;
  for (int j = 32; j != 0; j >>= 1, m ^= (m << j)) {
    for (int k = 0; k < 64; k = ((k | j) + 1) & ~j) {
      const uint64_t t = ((a[k] >> j) ^ a[k | j]) & m;
      a[k] ^= t << j;
      a[k | j] ^= t;
    }
  }
}

static std::string shortestDouble(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string binvoxHeader(const Dims& dims, const GridFrame& f) {
  const int32_t d = std::max({dims.nx, dims.ny, dims.nz});
  return "#binvox 1\ndim " + std::to_string(d) + " " + std::to_string(d) + " " + std::to_string(d) + "\ntranslate " +
         shortestDouble(f.origin.x) + " " + shortestDouble(f.origin.y) + " " + shortestDouble(f.origin.z) + "\nscale " +
         shortestDouble(double(d) * f.voxel_size) + "\ndata\n";
}

}  // namespace binvox_detail

}  // namespace vox::io
