// .vxm files larger than memory (vox/io/vxm_stream.h): the encoder a slab of layers at a time (it is also the
// whole-grid encoder, vxm.cpp), and a decoder that hands out windows of Z layers. The runs of the body run over the
// x-fastest voxel order across layers, so a layer's voxels are a contiguous stretch of the run sequence: a slab
// appends its stretch, a window takes its stretch, and a run crossing the boundary is carried over.
#include "vox/io/vxm_stream.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>

#include "io/voxel_file_common.h"
#include "io/vxm_detail.h"
#include "vox/core/text.h"
#include "vox/io/voxel_file.h"

namespace vox::io {

using namespace vxm_detail;
using voxel_file_detail::crc32Of;
using voxel_file_detail::emitRuns;

// ---- Writing

namespace {

// The runs of layers [z0, z1) of `grid` into `enc` (which writes into `out`), a row at a time.
void encodeLayers(const VoxelGrid& grid, int32_t z0, int32_t z1, RunEncoder& enc, const Writer& out,
                  std::vector<uint64_t>& words) {
  const uint64_t layer_voxels = uint64_t(grid.nx()) * uint64_t(grid.ny());
  words.resize(size_t((int64_t(grid.nx()) + 63) / 64));
  for (int32_t z = z0; z < z1 && out.status().ok(); ++z) {
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

}  // namespace

std::vector<uint8_t> encodeVxmLayers(const VoxelGrid& grid, int32_t z0, int32_t z1) {
  Writer out;
  RunEncoder enc(out);
  std::vector<uint64_t> words;
  encodeLayers(grid, std::max(z0, 0), std::min(z1, grid.nz()), enc, out, words);
  enc.finish();
  return std::move(out.bytes);
}

struct VxmLayerWriter::State {
  State(ByteSink& s, const Dims& d) : sink(s), dims(d), body(&s), enc(body) {}
  ByteSink& sink;
  Dims dims;
  Writer header;
  Writer body;
  RunEncoder enc;
  size_t header_size_at = 0, counts_at = 0, header_crc_at = 0;
  Status status = Ok{};
  int32_t layers = 0;  // appended so far
  std::vector<uint64_t> words;
};

VxmLayerWriter::VxmLayerWriter(ByteSink& sink, const Dims& dims, const GridFrame& f)
    : state_(std::make_unique<State>(sink, dims)) {
  Writer& w = state_->header;
  w.bytes.reserve(4096);
  w.bytes.insert(w.bytes.end(), std::begin(kVxmMagic), std::end(kVxmMagic));
  w.u32(kVxmVersion);
  state_->header_size_at = w.bytes.size();
  w.u32(0);  // header size, patched below
  w.u32(uint32_t(dims.nx));
  w.u32(uint32_t(dims.ny));
  w.u32(uint32_t(dims.nz));
  w.f64(f.origin.x);
  w.f64(f.origin.y);
  w.f64(f.origin.z);
  w.f64(f.voxel_size);
  state_->counts_at = w.bytes.size();
  w.u64(0);  // filled, runs and body size, patched by finish()
  w.u64(0);
  w.u64(0);
  w.text(f.units);
  w.text(f.source);
  state_->header_crc_at = w.bytes.size();
  w.u32(0);
  w.patchU32(state_->header_size_at, uint32_t(w.bytes.size()));
  state_->status = sink.append(w.bytes);
  state_->words.resize(size_t((int64_t(dims.nx) + 63) / 64));
}

VxmLayerWriter::~VxmLayerWriter() = default;

uint64_t VxmLayerWriter::filled() const { return state_->enc.filled(); }
uint64_t VxmLayerWriter::bodyBytes() const { return state_->body.streamed(); }

Status VxmLayerWriter::append(const VoxelGrid& grid, int32_t z0, int32_t z1) {
  State& s = *state_;
  if (!s.status.ok()) return s.status;
  if (grid.nx() != s.dims.nx || grid.ny() != s.dims.ny || z0 < 0 || z1 > grid.nz() || z1 < z0 ||
      s.layers + (z1 - z0) > s.dims.nz) {
    return makeError(ErrorCode::kInvalidArgument, "VxmLayerWriter: layers that do not belong to the grid");
  }
  encodeLayers(grid, z0, z1, s.enc, s.body, s.words);
  s.layers += z1 - z0;
  s.status = s.body.status();
  return s.status;
}

Status VxmLayerWriter::appendRuns(std::span<const uint8_t> runs, int32_t layers) {
  State& s = *state_;
  if (!s.status.ok()) return s.status;
  if (layers < 0 || s.layers + layers > s.dims.nz) {
    return makeError(ErrorCode::kInvalidArgument, "VxmLayerWriter: layers that do not belong to the grid");
  }
  const uint64_t voxels = uint64_t(s.dims.nx) * uint64_t(s.dims.ny) * uint64_t(layers);
  uint64_t covered = 0;
  bool filled = false;
  const uint8_t* p = runs.data();
  const uint8_t* const end = p + runs.size();
  while (p < end && s.body.status().ok()) {
    uint64_t n = 0;
    if (!readVarint(p, end, n) || n > voxels - covered) {
      s.status =
          Status(makeError(ErrorCode::kCorrupt, "VxmLayerWriter: runs that do not encode " + std::to_string(layers) +
                                                    " layers (a bad varint, or more voxels than they hold)"));
      return s.status;
    }
    s.enc.add(filled, n);  // the encoder joins a run that continues across the boundary
    covered += n;
    filled = !filled;
  }
  if (s.body.status().ok() && covered != voxels) {
    s.status = Status(makeError(ErrorCode::kCorrupt, "VxmLayerWriter: runs cover " + std::to_string(covered) +
                                                         " of the " + std::to_string(voxels) + " voxels of " +
                                                         std::to_string(layers) + " layers"));
    return s.status;
  }
  s.layers += layers;
  s.status = s.body.status();
  return s.status;
}

Status VxmLayerWriter::finish() {
  State& s = *state_;
  if (!s.status.ok()) return s.status;
  if (s.layers != s.dims.nz) {
    return makeError(ErrorCode::kInvalidArgument, "VxmLayerWriter: " + std::to_string(s.layers) + " of " +
                                                      std::to_string(s.dims.nz) + " layers written");
  }
  s.enc.finish();
  if (Status st = s.body.flush(); !st.ok()) return st;
  Writer& w = s.header;
  w.patchU64(s.counts_at, s.enc.filled());
  w.patchU64(s.counts_at + 8, s.enc.runs());
  w.patchU64(s.counts_at + 16, s.body.streamed());
  w.patchU32(s.header_crc_at, crc32Of(w.bytes.data(), s.header_crc_at));
  if (Status st = s.sink.overwrite(0, w.bytes); !st.ok()) return st;
  const uint32_t file_crc =
      uint32_t(::crc32_combine(crc32Of(w.bytes.data(), w.bytes.size()), s.body.crc(), z_off_t(s.body.streamed())));
  Writer tail;
  tail.u32(file_crc);
  s.status = s.sink.append(tail.bytes);
  return s.status;
}

Status saveVxmInSlabs(const std::filesystem::path& path, const Dims& dims, const GridFrame& frame,
                      const std::function<Status(VxmLayerWriter&)>& produce) {
  return writeFileAtomic(path, [&](ByteSink& sink) {
    VxmLayerWriter writer(sink, dims, frame);
    if (Status s = produce(writer); !s.ok()) return s;
    return writer.finish();
  });
}

int32_t layersWithin(const Dims& dims, uint64_t bytes) {
  const uint64_t layer = estimateGridBytes(Dims{dims.nx, dims.ny, 1}) - estimateGridBytes(Dims{dims.nx, dims.ny, 0});
  return int32_t(std::clamp<uint64_t>(bytes / std::max<uint64_t>(layer, 1), 1, uint64_t(std::max(dims.nz, 1))));
}

// ---- Reading

namespace {

// A file read in chunks with a read error that names it.
class ChunkedFile {
 public:
  static constexpr size_t kChunk = size_t(1) << 20;
  ~ChunkedFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  Status open(const std::filesystem::path& path) {
    name_ = path.string();
    do {
      fd_ = ::open(name_.c_str(), O_RDONLY | O_CLOEXEC);
    } while (fd_ < 0 && errno == EINTR);
    if (fd_ < 0) return makeError(ErrorCode::kIo, name_ + ": cannot open: " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd_, &st) != 0) return makeError(ErrorCode::kIo, name_ + ": cannot stat: " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) return makeError(ErrorCode::kIo, name_ + ": is a directory, not a file");
    size_ = uint64_t(st.st_size);
    return Ok{};
  }
  uint64_t size() const { return size_; }
  // Up to n bytes at `offset` (fewer only at the end of the file).
  Status readAt(uint64_t offset, size_t n, std::vector<uint8_t>& out) {
    out.resize(n);
    size_t done = 0;
    while (done < n) {
      const ssize_t r = ::pread(fd_, out.data() + done, n - done, off_t(offset + done));
      if (r < 0 && errno == EINTR) continue;
      if (r < 0) return makeError(ErrorCode::kIo, name_ + ": read failed: " + std::strerror(errno));
      if (r == 0) break;
      done += size_t(r);
    }
    out.resize(done);
    return Ok{};
  }

 private:
  int fd_ = -1;
  std::string name_;
  uint64_t size_ = 0;
};

// The header, from the file's first bytes.
Result<VxmHeader> readHeader(ChunkedFile& file, const std::string& name) {
  std::vector<uint8_t> head;
  if (Status s = file.readAt(0, size_t(std::min<uint64_t>(file.size(), kVxmMaxHeaderBytes + 4)), head); !s.ok()) {
    return s.error();
  }
  return parseVxmHeader(head, name);
}

// loadVxm's checks of the file's length and CRC, over the file in chunks.
Status checkLengthAndCrc(ChunkedFile& file, const VxmHeader& h, const std::string& name, bool check_crc) {
  const uint64_t size = file.size();
  if (Status s = checkVxmLength(size, h, name); !s) return s;
  if (!check_crc) return Ok{};
  uint32_t crc = 0;
  std::vector<uint8_t> chunk;
  for (uint64_t at = 0; at < size - 4; at += ChunkedFile::kChunk) {
    if (Status s = file.readAt(at, size_t(std::min<uint64_t>(ChunkedFile::kChunk, size - 4 - at)), chunk); !s.ok()) {
      return s;
    }
    crc = crc32Of(chunk.data(), chunk.size(), crc);
  }
  if (Status s = file.readAt(size - 4, 4, chunk); !s.ok()) return s;
  uint32_t stored = 0;
  for (int i = 3; i >= 0; --i) stored = (stored << 8) | chunk[size_t(i)];
  if (stored != crc) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CRC-32 mismatch (stored %08x, computed %08x)", stored, crc);
    return makeError(ErrorCode::kCorrupt, name + ": .vxm file is corrupt: " + buf);
  }
  return Ok{};
}

// The body's runs, one after another, read in chunks, checked as checkVxmBody (vxm.cpp) checks them.
class RunSource {
 public:
  RunSource(ChunkedFile& file, const VxmHeader& h, const std::string& name)
      : file_(file),
        h_(h),
        name_(name),
        end_(h.header_bytes + h.body_bytes),
        total_(uint64_t(h.dims.count())),
        buf_start_(h.header_bytes) {}
  // The next run into n (the voxels it covers, from `covered()` on); false at the end of the body.
  Result<bool> next(uint64_t& n) {
    if (!refill()) return false;
    const uint8_t* p = buf_.data() + at_;
    const uint8_t* end = buf_.data() + buf_.size();
    const bool ok = readVarint(p, end, n);
    at_ = size_t(p - buf_.data());
    if (!ok) return bodyError("bad run length at body byte " + std::to_string(bodyOffset()));
    if (n == 0 && runs_ > 0) return bodyError("empty run " + std::to_string(runs_ + 1));
    if (n > total_ - covered_) return bodyError("runs cover more than the " + std::to_string(total_) + " voxels");
    if (runs_ % 2 == 1) filled_ += n;  // runs alternate empty, filled, ...: odd runs are filled
    covered_ += n;
    ++runs_;
    return true;
  }
  // True when the run last returned is a filled one.
  bool filledRun() const { return runs_ % 2 == 0; }
  Status finish() {
    if (covered_ != total_) {
      return bodyError("runs cover " + std::to_string(covered_) + " of " + std::to_string(total_) + " voxels");
    }
    if (runs_ != h_.runs || filled_ != h_.filled) {
      return bodyError("header says " + std::to_string(h_.runs) + " runs and " + std::to_string(h_.filled) +
                       " filled voxels, body has " + std::to_string(runs_) + " and " + std::to_string(filled_));
    }
    return Ok{};
  }
  Status ioStatus() const { return io_; }

 private:
  Error bodyError(const std::string& what) const {
    return makeError(ErrorCode::kCorrupt, name_ + ": .vxm body is inconsistent: " + what);
  }
  uint64_t bodyOffset() const { return buf_start_ + at_ - h_.header_bytes; }
  // Keeps at least 10 bytes (a whole varint) buffered where the body has them; false at the body's end.
  bool refill() {
    if (buf_.size() - at_ >= 10 || buf_start_ + buf_.size() >= end_) return at_ < buf_.size();
    buf_start_ += at_;
    buf_.erase(buf_.begin(), buf_.begin() + std::ptrdiff_t(at_));
    at_ = 0;
    std::vector<uint8_t> more;
    const uint64_t from = buf_start_ + buf_.size();
    io_ = file_.readAt(from, size_t(std::min<uint64_t>(ChunkedFile::kChunk, end_ - from)), more);
    buf_.insert(buf_.end(), more.begin(), more.end());
    return at_ < buf_.size();
  }

  ChunkedFile& file_;
  const VxmHeader& h_;
  const std::string& name_;
  uint64_t end_, total_;
  uint64_t buf_start_;  // file offset of buf_[0]
  std::vector<uint8_t> buf_;
  size_t at_ = 0;
  uint64_t covered_ = 0, filled_ = 0, runs_ = 0;
  Status io_ = Ok{};
};

// Fills voxels [a, b) (x-fastest indices) into `grid`, whose layer 0 is the file's layer z_offset.
void fillSpan(VoxelGrid& grid, const Dims& d, int32_t z_offset, uint64_t a, uint64_t b) {
  const uint64_t nx = uint64_t(d.nx), ny = uint64_t(d.ny);
  while (a < b) {
    const uint64_t row = a / nx;
    const uint64_t x0 = a - row * nx;
    const uint64_t x1 = std::min<uint64_t>(nx, x0 + (b - a));
    grid.fillRun(int32_t(row % ny), int32_t(row / ny) - z_offset, int64_t(x0), int64_t(x1));
    a += x1 - x0;
  }
}

}  // namespace

Result<VxmHeaderInfo> readVxmHeader(const std::filesystem::path& path) {
  ChunkedFile file;
  if (Status s = file.open(path); !s.ok()) return s.error();
  auto h = readHeader(file, path.string());
  if (!h) return h.error();
  return VxmHeaderInfo{h->dims, h->frame, h->filled, h->runs, h->body_bytes};
}

Status readVxmInWindows(const std::filesystem::path& path, int32_t layers, int32_t halo,
                        const std::function<Status(const VxmWindow&)>& visit, bool check_crc) {
  const std::string name = path.string();
  ChunkedFile file;
  if (Status s = file.open(path); !s.ok()) return s;
  auto header = readHeader(file, name);
  if (!header) return header.error();
  const VxmHeader& h = *header;
  if (Status s = checkLengthAndCrc(file, h, name, check_crc); !s.ok()) return s;
  const Dims d = h.dims;
  const uint64_t lv = uint64_t(d.nx) * uint64_t(d.ny);
  layers = std::max(layers, 1);
  halo = std::max(halo, 0);
  RunSource runs(file, h, name);
  uint64_t pos = 0, left = 0;  // next voxel to place; voxels of the current run not yet placed
  bool filled = false;
  std::vector<std::vector<uint64_t>> carried;  // layers [carried_from, decoded) of the last window
  int32_t carried_from = 0;
  for (int32_t core = 0; core < d.nz; core += layers) {
    const int32_t core_end = std::min(d.nz, core + layers);
    const int32_t lo = std::max(0, core - halo), hi = std::min(d.nz, core_end + halo);
    VoxelGrid window(Dims{d.nx, d.ny, hi - lo}, h.frame);
    for (size_t i = 0; i < carried.size(); ++i) {
      const int32_t z = carried_from + int32_t(i) - lo;
      if (!carried[i].empty()) std::copy(carried[i].begin(), carried[i].end(), window.mutableLayerWords(z));
    }
    const uint64_t target = uint64_t(hi) * lv;
    while (pos < target) {
      if (left == 0) {
        uint64_t n = 0;
        auto more = runs.next(n);
        if (!more) return more.error();
        if (!runs.ioStatus().ok()) return runs.ioStatus();
        if (!*more) return runs.finish();  // runs short of the grid: finish() says so
        left = n;
        filled = runs.filledRun();
        continue;
      }
      const uint64_t take = std::min(left, target - pos);
      if (filled) fillSpan(window, d, lo, pos, pos + take);
      pos += take;
      left -= take;
    }
    // Layers the next window shares with this one.
    carried.clear();
    carried_from = std::max(lo, core_end - halo);
    for (int32_t z = carried_from; z < hi; ++z) {
      const uint64_t* w = window.layerWords(z - lo);
      carried.emplace_back();
      if (window.layerAllocated(z - lo)) carried.back().assign(w, w + window.wordsPerLayer());
    }
    if (Status s = visit(VxmWindow{window, lo, core, core_end}); !s.ok()) return s;
  }
  // Every voxel is placed: any run left in the body is one too many (next() says which error).
  for (;;) {
    uint64_t n = 0;
    auto more = runs.next(n);
    if (!more) return more.error();
    if (!*more) break;
  }
  if (!runs.ioStatus().ok()) return runs.ioStatus();
  return runs.finish();
}

}  // namespace vox::io
