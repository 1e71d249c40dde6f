// .vxm, voxmod's own voxel file. It follows the thesis's run-length file (section 4.2.2): "the starting run-length is
// always interpreted as of empty voxels ... and then follows the run-lengths for filled and empty voxels alternately",
// with the runs taken over the x-fastest voxel order and stored as LEB128 varints, behind a PNG-style magic, a version
// and a header CRC, and followed by a CRC-32 of the whole file. docs/file-format.md gives the layout byte by byte.
//
// Encoding finds the runs on whole 64-bit words of a row (emitRuns), so it costs O(words + runs), not O(voxels);
// decoding fills runs with VoxelGrid::fillRun.
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "io/voxel_file_common.h"
#include "io/vxm_detail.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/voxel_file.h"
#include "vox/io/vxm_stream.h"

namespace vox::io {

namespace {

using voxel_file_detail::checkLayerMemory;
using voxel_file_detail::crc32Of;
using voxel_file_detail::emitRuns;
using voxel_file_detail::encodeToMemory;
using voxel_file_detail::Writer;
using namespace vxm_detail;

Status checkDims(const Dims& d, const std::string& name) {
  const int32_t k = VoxelGrid::kMaxDim;
  if (d.nx < 1 || d.ny < 1 || d.nz < 1 || d.nx > k || d.ny > k || d.nz > k) {
    return makeError(ErrorCode::kLimit,
                     name + ": grid dimensions " + dimsText(d) + " are outside 1.." + std::to_string(k) + " per axis");
  }
  return Ok{};
}

// The .vxm encoder, streamed (VxmLayerWriter, vxm_stream.cpp): the whole grid as one slab.
Status encodeVxmTo(const VoxelGrid& grid, ByteSink& sink) {
  VxmLayerWriter writer(sink, grid.dims(), grid.frame());
  if (Status s = writer.append(grid, 0, grid.nz()); !s.ok()) return s;
  return writer.finish();
}

// Whole-file size and CRC.
Status checkVxmFile(std::span<const uint8_t> bytes, const VxmHeader& h, const std::string& name) {
  const uint8_t* b = bytes.data();
  const size_t size = bytes.size();
  if (Status s = vxm_detail::checkVxmLength(size, h, name); !s) return s;
  const uint32_t stored = loadLE<uint32_t>(b + size - 4);
  const uint32_t computed = crc32Of(b, size - 4);
  if (stored != computed) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CRC-32 mismatch (stored %08x, computed %08x)", stored, computed);
    return makeError(ErrorCode::kCorrupt, name + ": .vxm file is corrupt: " + buf);
  }
  return Ok{};
}

// Pass 1: check the runs add up, and count the Z layers they fill, before allocating anything.
Status checkVxmBody(const VxmHeader& h, const uint8_t* body, const uint8_t* body_end, const std::string& name,
                    uint64_t memory_limit_bytes) {
  const uint64_t total = uint64_t(h.dims.count());
  const uint64_t layer_voxels = uint64_t(h.dims.nx) * uint64_t(h.dims.ny);
  auto bodyError = [&](const std::string& what) {
    return makeError(ErrorCode::kCorrupt, name + ": .vxm body is inconsistent: " + what);
  };
  const uint8_t* p = body;
  uint64_t pos = 0, runs = 0, filled = 0;
  int64_t layers = 0, last_layer = -1;
  bool state = false;
  while (p < body_end) {
    uint64_t n;
    if (!readVarint(p, body_end, n)) return bodyError("bad run length at body byte " + std::to_string(p - body));
    if (n == 0 && runs > 0) return bodyError("empty run " + std::to_string(runs + 1));
    if (n > total - pos) return bodyError("runs cover more than the " + std::to_string(total) + " voxels");
    if (state && n > 0) {
      filled += n;
      const int64_t z0 = int64_t(pos / layer_voxels), z1 = int64_t((pos + n - 1) / layer_voxels);
      if (z1 > last_layer) {
        layers += z1 - std::max(z0, last_layer + 1) + 1;
        last_layer = z1;
      }
    }
    pos += n;
    ++runs;
    state = !state;
  }
  if (pos != total) {
    return bodyError("runs cover " + std::to_string(pos) + " of " + std::to_string(total) + " voxels");
  }
  if (runs != h.runs || filled != h.filled) {
    return bodyError("header says " + std::to_string(h.runs) + " runs and " + std::to_string(h.filled) +
                     " filled voxels, body has " + std::to_string(runs) + " and " + std::to_string(filled));
  }
  if (Status s = checkLayerMemory(h.dims, layers, name, memory_limit_bytes); !s.ok()) return s.error();
  return Ok{};
}

// Pass 2: fill the grid from a body that checkVxmBody accepted.
void fillVxmBody(VoxelGrid& grid, const VxmHeader& h, const uint8_t* body, const uint8_t* body_end) {
  const uint8_t* p = body;
  uint64_t pos = 0;
  bool state = false;
  const uint64_t nx = uint64_t(h.dims.nx);
  while (p < body_end) {
    uint64_t n;
    readVarint(p, body_end, n);
    if (state) {
      uint64_t start = pos;
      const uint64_t end = pos + n;
      while (start < end) {
        const uint64_t row = start / nx;
        const uint64_t x0 = start - row * nx;
        const uint64_t x1 = std::min<uint64_t>(nx, x0 + (end - start));
        grid.fillRun(int32_t(row % uint64_t(h.dims.ny)), int32_t(row / uint64_t(h.dims.ny)), int64_t(x0), int64_t(x1));
        start += x1 - x0;
      }
    }
    pos += n;
    state = !state;
  }
}

}  // namespace

namespace vxm_detail {

// Voxel bits of row (y, z) as unpadded words: bit b of word w is voxel x = 64 w + b. Bits past nx are zero.
void unpaddedRow(const VoxelGrid& grid, int32_t y, int32_t z, std::vector<uint64_t>& out) {
  const uint64_t* row = grid.rowWords(y, z);
  const int64_t wpr = grid.wordsPerRow();
  const int64_t n = (int64_t(grid.nx()) + 63) / 64;
  for (int64_t w = 0; w < n; ++w) {
    const uint64_t hi = w + 1 < wpr ? row[w + 1] : 0;
    out[size_t(w)] = (row[w] >> 1) | (hi << 63);
  }
  const int tail = grid.nx() & 63;
  if (tail) out[size_t(n - 1)] &= (uint64_t(1) << tail) - 1;
}

// The header: magic and version, then the fields under their own CRC, so that a truncated body is told apart
// from a damaged header.
// A file of `size` bytes holds exactly the header, the body and the CRC the header describes.
Status checkVxmLength(uint64_t size, const VxmHeader& h, const std::string& name) {
  const uint64_t expected = uint64_t(h.header_bytes) + h.body_bytes + 4;
  if (h.body_bytes > size || size < expected) {
    return makeError(ErrorCode::kParse, name + ": .vxm file truncated: expected " + std::to_string(expected) +
                                            " bytes but the file has " + std::to_string(size));
  }
  if (size > expected) {
    return makeError(ErrorCode::kCorrupt,
                     name + ": .vxm file has " + std::to_string(size - expected) + " unexpected bytes after its end");
  }
  return Ok{};
}

Result<VxmHeader> parseVxmHeader(std::span<const uint8_t> bytes, const std::string& name) {
  const uint8_t* b = bytes.data();
  const size_t size = bytes.size();
  if (size < sizeof kVxmMagic || std::memcmp(b, kVxmMagic, sizeof kVxmMagic) != 0) {
    if (size < sizeof kVxmMagic && std::memcmp(b, kVxmMagic, size) == 0 && size > 0) {
      return makeError(ErrorCode::kParse, name + ": .vxm file truncated: " + std::to_string(size) + " bytes");
    }
    return makeError(ErrorCode::kParse, name + ": not a voxmod .vxm file (bad magic bytes)");
  }
  if (size < 12)
    return makeError(ErrorCode::kParse, name + ": .vxm file truncated: " + std::to_string(size) + " bytes");
  const uint32_t version = loadLE<uint32_t>(b + 8);
  if (version > kVxmVersion) {
    return makeError(ErrorCode::kUnsupported, name + ": written by a newer voxmod (format version " +
                                                  std::to_string(version) + "; this build reads up to " +
                                                  std::to_string(kVxmVersion) + ")");
  }
  if (version == 0) return makeError(ErrorCode::kCorrupt, name + ": invalid .vxm format version 0");
  if (size < kVxmMinBytes) {
    return makeError(ErrorCode::kParse,
                     name + ": .vxm file truncated: " + std::to_string(size) + " bytes, shorter than any .vxm header");
  }

  VxmHeader h;
  h.header_bytes = loadLE<uint32_t>(b + 12);
  if (h.header_bytes < kVxmFixedBytes + 8 || h.header_bytes > kVxmFixedBytes + 8 + 2 * 0xFFFF) {
    return makeError(ErrorCode::kCorrupt,
                     name + ": .vxm header is corrupt (header size " + std::to_string(h.header_bytes) + ")");
  }
  if (size < h.header_bytes + 4) {
    return makeError(ErrorCode::kParse, name + ": .vxm file truncated: the header needs " +
                                            std::to_string(h.header_bytes) + " bytes but the file has " +
                                            std::to_string(size));
  }
  const uint32_t header_crc = loadLE<uint32_t>(b + h.header_bytes - 4);
  if (crc32Of(b, h.header_bytes - 4) != header_crc) {
    return makeError(ErrorCode::kCorrupt, name + ": .vxm header is corrupt (CRC-32 mismatch)");
  }
  h.dims = {int32_t(loadLE<uint32_t>(b + 16)), int32_t(loadLE<uint32_t>(b + 20)), int32_t(loadLE<uint32_t>(b + 24))};
  if (loadLE<uint32_t>(b + 16) > uint32_t(INT32_MAX) || loadLE<uint32_t>(b + 20) > uint32_t(INT32_MAX) ||
      loadLE<uint32_t>(b + 24) > uint32_t(INT32_MAX)) {
    h.dims = {-1, -1, -1};
  }
  h.frame.origin = {std::bit_cast<double>(loadLE<uint64_t>(b + 28)), std::bit_cast<double>(loadLE<uint64_t>(b + 36)),
                    std::bit_cast<double>(loadLE<uint64_t>(b + 44))};
  h.frame.voxel_size = std::bit_cast<double>(loadLE<uint64_t>(b + 52));
  h.filled = loadLE<uint64_t>(b + 60);
  h.runs = loadLE<uint64_t>(b + 68);
  h.body_bytes = loadLE<uint64_t>(b + 76);
  size_t at = kVxmFixedBytes;
  for (std::string* s : {&h.frame.units, &h.frame.source}) {
    const size_t n = loadLE<uint16_t>(b + at);
    if (at + 2 + n + 4 > h.header_bytes) {
      return makeError(ErrorCode::kCorrupt, name + ": .vxm header is corrupt (string lengths exceed the header)");
    }
    s->assign(reinterpret_cast<const char*>(b + at + 2), n);
    at += 2 + n;
  }
  if (at + 4 != h.header_bytes) {
    return makeError(ErrorCode::kCorrupt, name + ": .vxm header is corrupt (header size does not match its fields)");
  }
  if (Status s = checkDims(h.dims, name); !s.ok()) return s.error();
  if (!std::isfinite(h.frame.origin.x) || !std::isfinite(h.frame.origin.y) || !std::isfinite(h.frame.origin.z) ||
      !std::isfinite(h.frame.voxel_size) || !(h.frame.voxel_size > 0)) {
    return makeError(ErrorCode::kCorrupt, name +
                                              ": .vxm header has a non-finite origin or a voxel size that is not "
                                              "positive");
  }
  return h;
}

}  // namespace vxm_detail

std::vector<uint8_t> encodeVxm(const VoxelGrid& grid) { return encodeToMemory(encodeVxmTo, grid); }

Result<VoxelGrid> decodeVxm(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit_bytes) {
  auto header = parseVxmHeader(bytes, name);
  if (!header.ok()) return header.error();
  const VxmHeader& h = header.value();
  if (Status s = checkVxmFile(bytes, h, name); !s.ok()) return s.error();
  const uint8_t* body = bytes.data() + h.header_bytes;
  const uint8_t* body_end = body + h.body_bytes;
  if (Status s = checkVxmBody(h, body, body_end, name, memory_limit_bytes); !s.ok()) return s.error();
  VoxelGrid grid(h.dims, h.frame);
  fillVxmBody(grid, h, body, body_end);
  return grid;
}

Status saveVxm(const VoxelGrid& grid, const std::filesystem::path& path) {
  if (grid.empty()) return makeError(ErrorCode::kInvalidArgument, path.string() + ": cannot save an empty grid");
  return writeFileAtomic(path, [&](ByteSink& sink) { return encodeVxmTo(grid, sink); });
}

Result<VoxelGrid> loadVxm(const std::filesystem::path& path) {
  auto bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.error();
  return decodeVxm(bytes.value(), path.string());
}

}  // namespace vox::io
