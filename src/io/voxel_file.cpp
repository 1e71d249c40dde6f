// Voxel files: voxmod's .vxm and the .binvox interchange format.
//
// .vxm follows the thesis's run-length file (section 4.2.2): "the starting run-length is always interpreted as of
// empty voxels ... and then follows the run-lengths for filled and empty voxels alternately", with the runs taken
// over the x-fastest voxel order and stored as LEB128 varints, behind a PNG-style magic, a version and a header
// CRC, and followed by a CRC-32 of the whole file. docs/file-format.md gives the layout byte by byte.
//
// .binvox follows Patrick Min's format (https://www.patrickmin.com/binvox/binvox.html) and SPEC section 4: ASCII
// header, then (value, count) byte pairs over the order y fastest, then z, then x.
//
// Both codecs work on 64-bit words where the data allows: .vxm runs are found with countr_zero on whole words of
// a row, so encoding costs O(words + runs), not O(voxels); decoding fills runs with VoxelGrid::fillRun.
#include "vox/io/voxel_file.h"

#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::io {

namespace {

// ---- Shared helpers ----

std::string baseName(const std::string& name) { return std::filesystem::path(name).filename().string(); }

Status checkDims(const Dims& d, const std::string& name) {
  const int32_t k = VoxelGrid::kMaxDim;
  if (d.nx < 1 || d.ny < 1 || d.nz < 1 || d.nx > k || d.ny > k || d.nz > k) {
    return makeError(ErrorCode::kLimit,
                     name + ": grid dimensions " + dimsText(d) + " are outside 1.." + std::to_string(k) + " per axis");
  }
  return Ok{};
}

// Memory for `layers` allocated Z layers of a grid with dims d, compared with the machine's memory.
// `extra` is working memory the decoder needs besides the grid.
Status checkLayerMemory(const Dims& d, int64_t layers, const std::string& name, uint64_t limit, uint64_t extra = 0) {
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

// ---- Little-endian byte writer / reader ----

// CRC-32 of n bytes, continuing from `crc` (the CRC of the bytes before them; 0 to start).
uint32_t crc32Of(const uint8_t* data, size_t n, uint32_t crc_before = 0) {
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

class Writer {
 public:
  Writer() = default;
  // Streaming: whenever a varint leaves more than kChunkBytes buffered, the buffer goes to `sink` (and into the
  // running CRC-32 of everything streamed); flush() sends the rest. The first failure is kept and later data dropped.
  explicit Writer(ByteSink* sink) : sink_(sink) {}
  static constexpr size_t kChunkBytes = size_t(1) << 20;

  std::vector<uint8_t> bytes;
  Status flush() {
    if (!sink_ || !status_.ok() || bytes.empty()) return status_;
    status_ = sink_->append(bytes);
    if (status_.ok()) {
      crc_ = crc32Of(bytes.data(), bytes.size(), crc_);
      streamed_ += bytes.size();
    }
    bytes.clear();
    return status_;
  }
  const Status& status() const { return status_; }
  uint64_t streamed() const { return streamed_; }  // bytes handed to the sink
  uint32_t crc() const { return crc_; }            // their CRC-32
  void u16(uint16_t v) { raw(&v, 2); }
  void u32(uint32_t v) { raw(&v, 4); }
  void u64(uint64_t v) { raw(&v, 8); }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  // Two bytes (a binvox run).
  void pair(uint8_t a, uint8_t b) {
    bytes.push_back(a);
    bytes.push_back(b);
    if (sink_ && bytes.size() >= kChunkBytes) (void)flush();  // a failure stays in status()
  }
  void varint(uint64_t v) {
    while (v >= 0x80) {
      bytes.push_back(uint8_t(v | 0x80));
      v >>= 7;
    }
    bytes.push_back(uint8_t(v));
    if (sink_ && bytes.size() >= kChunkBytes) (void)flush();  // a failure stays in status()
  }
  void text(const std::string& s) {
    const size_t n = std::min<size_t>(s.size(), 0xFFFF);  // longer strings are cut; the header field is 16-bit
    u16(uint16_t(n));
    bytes.insert(bytes.end(), s.begin(), s.begin() + std::ptrdiff_t(n));
  }
  void patchU64(size_t at, uint64_t v) { patch(at, &v, 8); }
  void patchU32(size_t at, uint32_t v) { patch(at, &v, 4); }

 private:
  template <class T>
  static T little(T v) {
    if constexpr (std::endian::native == std::endian::big) {
      if constexpr (sizeof(T) == 2) return T(__builtin_bswap16(v));
      if constexpr (sizeof(T) == 4) return T(__builtin_bswap32(v));
      if constexpr (sizeof(T) == 8) return T(__builtin_bswap64(v));
    }
    return v;
  }
  template <class T>
  void raw(const T* v, size_t n) {
    const T le = little(*v);
    const auto* p = reinterpret_cast<const uint8_t*>(&le);
    bytes.insert(bytes.end(), p, p + n);
  }
  template <class T>
  void patch(size_t at, const T* v, size_t n) {
    const T le = little(*v);
    std::memcpy(bytes.data() + at, &le, n);
  }

  ByteSink* sink_ = nullptr;
  Status status_ = Ok{};
  uint64_t streamed_ = 0;
  uint32_t crc_ = 0;
};

template <class T>
T loadLE(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    if constexpr (sizeof(T) == 2) v = T(__builtin_bswap16(v));
    if constexpr (sizeof(T) == 4) v = T(__builtin_bswap32(v));
    if constexpr (sizeof(T) == 8) v = T(__builtin_bswap64(v));
  }
  return v;
}

// A streaming encoder's output collected in memory (a memory sink does not fail).
std::vector<uint8_t> encodeToMemory(Status (*encode)(const VoxelGrid&, ByteSink&), const VoxelGrid& grid) {
  VectorSink sink;
  (void)encode(grid, sink);
  return std::move(sink.bytes);
}

// ---- .vxm ----

constexpr uint8_t kVxmMagic[8] = {0x89, 'V', 'X', 'M', '\r', '\n', 0x1A, '\n'};
constexpr size_t kVxmFixedBytes = 84;                            // magic .. body size, before the two strings
constexpr size_t kVxmMinBytes = kVxmFixedBytes + 2 + 2 + 4 + 4;  // empty strings, header CRC, file CRC

// Emits alternating runs, starting with an empty one, as varints.
class RunEncoder {
 public:
  explicit RunEncoder(Writer& w) : w_(w) {}
  void add(bool filled, uint64_t n) {
    if (n == 0) return;
    if (filled != state_) {
      w_.varint(run_);
      ++runs_;
      run_ = 0;
      state_ = filled;
    }
    run_ += n;
    if (filled) filled_ += n;
  }
  void finish() {
    w_.varint(run_);
    ++runs_;
  }
  uint64_t runs() const { return runs_; }
  uint64_t filled() const { return filled_; }

 private:
  Writer& w_;
  bool state_ = false;
  uint64_t run_ = 0;
  uint64_t runs_ = 0;
  uint64_t filled_ = 0;
};

// Calls sink.add(value, length) for the runs of the first `nbits` bits of `words` (bit b of word w is element
// 64 w + b). Whole empty or full words cost O(1); otherwise one countr_zero per run. Zero-length runs may be
// passed; sinks ignore them.
template <class Sink>
void emitRuns(const uint64_t* words, int64_t nbits, Sink& sink) {
  bool state = false;
  const int64_t n = (nbits + 63) / 64;
  for (int64_t w = 0; w < n; ++w) {
    const int bits = (w + 1 == n && (nbits & 63)) ? int(nbits & 63) : 64;
    const uint64_t valid = bits == 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
    int pos = 0;
    while (pos < bits) {
      // Bits that differ from the current state, from pos on: the run of `state` ends at the first of them.
      const uint64_t diff = ((state ? ~words[w] : words[w]) & valid) >> pos;
      const int len = diff == 0 ? bits - pos : std::countr_zero(diff);
      sink.add(state, uint64_t(len));
      pos += len;
      if (pos < bits) state = !state;
    }
  }
}

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

// Parsed .vxm header fields.
struct VxmHeader {
  Dims dims;
  GridFrame frame;
  uint64_t filled = 0, runs = 0, body_bytes = 0;
  size_t header_bytes = 0;  // offset of the body
};

// Reads one LEB128 varint of at most 10 bytes; false when it is truncated or overlong.
bool readVarint(const uint8_t*& p, const uint8_t* end, uint64_t& v) {
  v = 0;
  for (int shift = 0; shift < 64 && p < end; shift += 7) {
    const uint8_t b = *p++;
    if (shift == 63 && b > 1) return false;  // would overflow 64 bits
    v |= uint64_t(b & 0x7F) << shift;
    if (!(b & 0x80)) return true;
  }
  return false;
}

// The .vxm encoder, streamed: the header with placeholder counts, the body in chunks of about a megabyte, then the
// completed header written over the placeholder and the file CRC (of the final header and the body, joined with
// crc32_combine) appended. Memory: one chunk and one row, whatever the grid.
Status encodeVxmTo(const VoxelGrid& grid, ByteSink& sink) {
  Writer w;
  w.bytes.reserve(4096);
  w.bytes.insert(w.bytes.end(), std::begin(kVxmMagic), std::end(kVxmMagic));
  w.u32(kVxmVersion);
  const size_t header_size_at = w.bytes.size();
  w.u32(0);  // header size, patched below
  w.u32(uint32_t(grid.nx()));
  w.u32(uint32_t(grid.ny()));
  w.u32(uint32_t(grid.nz()));
  const GridFrame& f = grid.frame();
  w.f64(f.origin.x);
  w.f64(f.origin.y);
  w.f64(f.origin.z);
  w.f64(f.voxel_size);
  const size_t counts_at = w.bytes.size();
  w.u64(0);  // filled, runs and body size, patched below
  w.u64(0);
  w.u64(0);
  w.text(f.units);
  w.text(f.source);
  const size_t header_crc_at = w.bytes.size();
  w.u32(0);
  w.patchU32(header_size_at, uint32_t(w.bytes.size()));
  if (Status s = sink.append(w.bytes); !s.ok()) return s;

  Writer body(&sink);
  RunEncoder enc(body);
  if (!grid.empty()) {
    const uint64_t layer_voxels = uint64_t(grid.nx()) * uint64_t(grid.ny());
    std::vector<uint64_t> words(size_t((int64_t(grid.nx()) + 63) / 64));
    for (int32_t z = 0; z < grid.nz() && body.status().ok(); ++z) {
      if (!grid.layerAllocated(z)) {
        enc.add(false, layer_voxels);
        continue;
      }
      for (int32_t y = 0; y < grid.ny(); ++y) {
        unpaddedRow(grid, y, z, words);
        emitRuns(words.data(), grid.nx(), enc);
      }
    }
  }
  enc.finish();
  if (Status s = body.flush(); !s.ok()) return s;
  w.patchU64(counts_at, enc.filled());
  w.patchU64(counts_at + 8, enc.runs());
  w.patchU64(counts_at + 16, body.streamed());
  w.patchU32(header_crc_at, crc32Of(w.bytes.data(), header_crc_at));
  if (Status s = sink.overwrite(0, w.bytes); !s.ok()) return s;
  const uint32_t file_crc =
      uint32_t(::crc32_combine(crc32Of(w.bytes.data(), w.bytes.size()), body.crc(), z_off_t(body.streamed())));
  Writer tail;
  tail.u32(file_crc);
  return sink.append(tail.bytes);
}

}  // namespace

std::vector<uint8_t> encodeVxm(const VoxelGrid& grid) { return encodeToMemory(encodeVxmTo, grid); }

Result<VoxelGrid> decodeVxm(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit_bytes) {
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

  // The header first, under its own CRC, so that a truncated body is told apart from a damaged header.
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

  // Whole-file size and CRC.
  const uint64_t expected = uint64_t(h.header_bytes) + h.body_bytes + 4;
  if (h.body_bytes > size || size < expected) {
    return makeError(ErrorCode::kParse, name + ": .vxm file truncated: expected " + std::to_string(expected) +
                                            " bytes but the file has " + std::to_string(size));
  }
  if (size > expected) {
    return makeError(ErrorCode::kCorrupt,
                     name + ": .vxm file has " + std::to_string(size - expected) + " unexpected bytes after its end");
  }
  const uint32_t stored = loadLE<uint32_t>(b + size - 4);
  const uint32_t computed = crc32Of(b, size - 4);
  if (stored != computed) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CRC-32 mismatch (stored %08x, computed %08x)", stored, computed);
    return makeError(ErrorCode::kCorrupt, name + ": .vxm file is corrupt: " + buf);
  }

  // Pass 1: check the runs add up, and count the Z layers they fill, before allocating anything.
  const uint64_t total = uint64_t(h.dims.count());
  const uint64_t layer_voxels = uint64_t(h.dims.nx) * uint64_t(h.dims.ny);
  const uint8_t* body = b + h.header_bytes;
  const uint8_t* body_end = body + h.body_bytes;
  auto bodyError = [&](const std::string& what) {
    return makeError(ErrorCode::kCorrupt, name + ": .vxm body is inconsistent: " + what);
  };
  {
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
  }

  // Pass 2: fill.
  VoxelGrid grid(h.dims, h.frame);
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

// ---- .binvox ----

namespace {

std::string shortestDouble(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool parseDouble(std::string_view s, double& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

bool parseInt(std::string_view s, int64_t& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// (value, count) byte pairs with counts of at most 255, merging adjacent runs of one value.
class BinvoxRuns {
 public:
  explicit BinvoxRuns(Writer& out) : out_(out) {}
  void add(bool filled, uint64_t n) {
    if (n == 0) return;
    if (uint8_t(filled) != value_) {
      flush();
      value_ = uint8_t(filled);
    }
    run_ += n;
  }
  void flush() {
    while (run_ > 0) {
      const uint64_t piece = std::min<uint64_t>(run_, 255);
      out_.pair(value_, uint8_t(piece));
      run_ -= piece;
    }
  }

 private:
  Writer& out_;
  uint8_t value_ = 0;
  uint64_t run_ = 0;
};

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

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

// The binvox encoder, streamed in chunks of about a megabyte (binvox has no checksum or counts to patch).
Status encodeBinvoxTo(const VoxelGrid& grid, ByteSink& sink) {
  const int32_t d = std::max({grid.nx(), grid.ny(), grid.nz()});
  const GridFrame& f = grid.frame();
  std::string header = "#binvox 1\ndim " + std::to_string(d) + " " + std::to_string(d) + " " + std::to_string(d) +
                       "\ntranslate " + shortestDouble(f.origin.x) + " " + shortestDouble(f.origin.y) + " " +
                       shortestDouble(f.origin.z) + "\nscale " + shortestDouble(double(d) * f.voxel_size) + "\ndata\n";
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

}  // namespace

std::vector<uint8_t> encodeBinvox(const VoxelGrid& grid) { return encodeToMemory(encodeBinvoxTo, grid); }

Result<VoxelGrid> decodeBinvox(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit_bytes) {
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
    if (words.size() != 1 || !parseInt(words[0], version)) return error(ErrorCode::kParse, "bad '#binvox' line");
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
      if (words.size() != 4 || !parseInt(words[1], v[0]) || !parseInt(words[2], v[1]) || !parseInt(words[3], v[2])) {
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
      if (words.size() != 4 || !parseDouble(words[1], translate.x) || !parseDouble(words[2], translate.y) ||
          !parseDouble(words[3], translate.z)) {
        return error(ErrorCode::kParse, "expected 'translate x y z' with three finite numbers");
      }
    } else if (words[0] == "scale") {
      if (words.size() != 2 || !parseDouble(words[1], scale) || !(scale > 0)) {
        return error(ErrorCode::kParse, "expected 'scale s' with a positive number");
      }
    } else {
      return error(ErrorCode::kParse, "unknown binvox header line " + quoteBytes(line));
    }
  }
  if (!have_data) return makeError(ErrorCode::kParse, name + ": binvox header has no 'data' line");
  if (!have_dim) return makeError(ErrorCode::kParse, name + ": binvox header has no 'dim' line");

  const uint64_t total = uint64_t(dims.count());
  const uint64_t width = uint64_t(dims.ny), height = uint64_t(dims.nz);
  const uint8_t* data = bytes.data() + pos;
  const size_t data_bytes = size - pos;
  const size_t pairs = data_bytes / 2;
  auto dataError = [&](ErrorCode code, const std::string& what) {
    return makeError(code, name + ": binvox data " + what);
  };

  // Pass 1: the runs must cover exactly D^3 voxels with values 0/1; note the Z layers that filled voxels touch.
  std::vector<uint8_t> layer_used(size_t(dims.nz), 0);
  {
    uint64_t covered = 0;
    for (size_t i = 0; i < pairs; ++i) {
      const uint8_t v = data[2 * i], n = data[2 * i + 1];
      if (v > 1) {
        return dataError(ErrorCode::kParse, "has value " + std::to_string(v) + " at byte " +
                                                std::to_string(pos + 2 * i) + " (values are 0 or 1)");
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
  }

  GridFrame frame;
  frame.origin = translate;
  // The file stores the edge of the cube the grid was fitted into (SPEC section 4): voxel size = scale / D, with
  // D the largest dimension when a file is not cubic.
  frame.voxel_size = scale / double(std::max({dims.nx, dims.ny, dims.nz}));
  frame.source = baseName(name);
  VoxelGrid grid(dims, frame);
  // Pass 2: the runs of 64 consecutive x values (a block of the file) are set into y-columns with word masks,
  // then 64 x 64 bit blocks are transposed into the grid's x-rows: the reverse of encodeBinvox.
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

}  // namespace vox::io
