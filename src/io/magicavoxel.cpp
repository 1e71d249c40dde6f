// MagicaVoxel .vox writer, after the public format description (github.com/ephtracy/voxel-model,
// MagicaVoxel-file-format-vox.txt and MagicaVoxel-file-format-vox-extension.txt). Two passes over the grid: the
// first counts the filled voxels of every 256^3 block (word popcounts), because a chunk's size precedes its content
// and the whole file's size must be known to refuse one over 2 GiB before writing anything; the second streams each
// model's voxels. The scene graph is small and built in memory.
#include "vox/io/magicavoxel.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <string>
#include <utility>

#include <glm/common.hpp>

#include "vox/core/text.h"

namespace vox::io {
namespace {

constexpr int32_t kVersion = 150;  // what MagicaVoxel writes with a scene graph; every reader takes it
constexpr uint64_t kChunkHeader = 12;
constexpr uint8_t kColour = 1;  // every filled voxel: palette index 1

// Little-endian bytes, buffered and sent to the sink in large pieces.
class Emitter {
 public:
  explicit Emitter(ByteSink* sink) : sink_(sink) {}
  std::vector<uint8_t> bytes;
  void i32(int32_t v) {
    const auto u = uint32_t(v);
    four(uint8_t(u), uint8_t(u >> 8), uint8_t(u >> 16), uint8_t(u >> 24));
  }
  void id(const char (&name)[5]) { four(uint8_t(name[0]), uint8_t(name[1]), uint8_t(name[2]), uint8_t(name[3])); }
  void string(const std::string& s) {
    i32(int32_t(s.size()));
    bytes.insert(bytes.end(), s.begin(), s.end());
  }
  void dict(const std::vector<std::pair<std::string, std::string>>& pairs) {
    i32(int32_t(pairs.size()));
    for (const auto& [k, v] : pairs) {
      string(k);
      string(v);
    }
  }
  void chunk(const char (&name)[5], const std::vector<uint8_t>& content) {
    id(name);
    i32(int32_t(content.size()));
    i32(0);
    bytes.insert(bytes.end(), content.begin(), content.end());
  }
  void voxel(int32_t x, int32_t y, int32_t z) {
    four(uint8_t(x), uint8_t(y), uint8_t(z), kColour);
    if (bytes.size() >= (size_t(1) << 20)) (void)flush();  // a failure stays in status_
  }
  Status flush() {
    if (status_.ok() && sink_ && !bytes.empty()) status_ = sink_->append(bytes);
    bytes.clear();
    return status_;
  }

 private:
  void four(uint8_t a, uint8_t b, uint8_t c, uint8_t d) {
    bytes.push_back(a);
    bytes.push_back(b);
    bytes.push_back(c);
    bytes.push_back(d);
  }
  ByteSink* sink_;
  Status status_ = Ok{};
};

// Filled voxels of row (y, z) among x in [x0, x1).
int64_t countRow(const VoxelGrid& grid, int32_t y, int32_t z, int32_t x0, int32_t x1) {
  const uint64_t* row = grid.rowWords(y, z);
  const int64_t b0 = int64_t(x0) + 1, b1 = int64_t(x1) + 1;  // padded bit positions
  int64_t n = 0;
  for (int64_t w = b0 >> 6; w <= (b1 - 1) >> 6; ++w) {
    uint64_t bits = row[w];
    if (w == b0 >> 6) bits &= ~uint64_t(0) << (b0 & 63);
    if (w == (b1 - 1) >> 6 && (b1 & 63) != 0) bits &= (uint64_t(1) << (b1 & 63)) - 1;
    n += std::popcount(bits);
  }
  return n;
}

// Calls f(x) for every filled voxel of row (y, z) with x in [x0, x1), in increasing x.
template <class F>
void forRowVoxels(const VoxelGrid& grid, int32_t y, int32_t z, int32_t x0, int32_t x1, F&& f) {
  const uint64_t* row = grid.rowWords(y, z);
  const int64_t b0 = int64_t(x0) + 1, b1 = int64_t(x1) + 1;
  for (int64_t w = b0 >> 6; w <= (b1 - 1) >> 6; ++w) {
    uint64_t bits = row[w];
    if (w == b0 >> 6) bits &= ~uint64_t(0) << (b0 & 63);
    if (w == (b1 - 1) >> 6 && (b1 & 63) != 0) bits &= (uint64_t(1) << (b1 & 63)) - 1;
    for (; bits != 0; bits &= bits - 1) f(int32_t(w * 64 + std::countr_zero(bits) - 1));
  }
}

int32_t blocksAlong(int32_t n) { return (n + kMagicaVoxelModelSize - 1) / kMagicaVoxelModelSize; }

// nTRN, nGRP, nSHP and LAYR chunks: a root transform over one group holding a transform + shape per model.
std::vector<uint8_t> sceneGraph(const std::vector<MagicaVoxelModel>& models) {
  Emitter out(nullptr);
  Emitter c(nullptr);
  auto transform = [&](int32_t node, int32_t child, int32_t layer, const std::string& name, const std::string& t) {
    c.bytes.clear();
    c.i32(node);
    c.dict(name.empty() ? std::vector<std::pair<std::string, std::string>>{}
                        : std::vector<std::pair<std::string, std::string>>{{"_name", name}});
    c.i32(child);
    c.i32(-1);  // reserved
    c.i32(layer);
    c.i32(1);  // frames
    c.dict(t.empty() ? std::vector<std::pair<std::string, std::string>>{}
                     : std::vector<std::pair<std::string, std::string>>{{"_t", t}});
    out.chunk("nTRN", c.bytes);
  };
  transform(0, 1, -1, "", "");
  c.bytes.clear();
  c.i32(1);
  c.dict({});
  c.i32(int32_t(models.size()));
  for (size_t i = 0; i < models.size(); ++i) c.i32(int32_t(2 + 2 * i));
  out.chunk("nGRP", c.bytes);
  for (size_t i = 0; i < models.size(); ++i) {
    const MagicaVoxelModel& m = models[i];
    // MagicaVoxel places a model by its centre, floor(size / 2) voxels from its first voxel.
    const glm::ivec3 t = m.first + m.size / 2;
    const std::string name =
        "voxels " + std::to_string(m.first.x) + " " + std::to_string(m.first.y) + " " + std::to_string(m.first.z);
    transform(int32_t(2 + 2 * i), int32_t(3 + 2 * i), 0, name,
              std::to_string(t.x) + " " + std::to_string(t.y) + " " + std::to_string(t.z));
    c.bytes.clear();
    c.i32(int32_t(3 + 2 * i));
    c.dict({});
    c.i32(1);  // models
    c.i32(int32_t(i));
    c.dict({});
    out.chunk("nSHP", c.bytes);
  }
  c.bytes.clear();
  c.i32(0);
  c.dict({{"_name", "voxmod"}});
  c.i32(-1);
  out.chunk("LAYR", c.bytes);
  return std::move(out.bytes);
}

// 256 RGBA entries; entry i is colour index i + 1. Index 1 (the voxels) light grey, the rest a grey ramp.
std::vector<uint8_t> palette() {
  std::vector<uint8_t> p;
  p.reserve(1024);
  for (int i = 0; i < 256; ++i) {
    const auto g = uint8_t(i == 0 ? 200 : 255 - i);
    p.push_back(g);
    p.push_back(g);
    p.push_back(g);
    p.push_back(255);
  }
  return p;
}

uint64_t modelBytes(const MagicaVoxelModel& m) { return kChunkHeader + 12 + kChunkHeader + 4 + 4 * uint64_t(m.voxels); }

// MAIN's children: the models, the scene graph and the palette.
uint64_t childrenBytes(const std::vector<MagicaVoxelModel>& models, uint64_t scene_bytes) {
  uint64_t n = scene_bytes + kChunkHeader + 1024;
  for (const MagicaVoxelModel& m : models) n += modelBytes(m);
  return n;
}

Status writeModel(const VoxelGrid& grid, const MagicaVoxelModel& m, Emitter& out) {
  out.id("SIZE");
  out.i32(12);
  out.i32(0);
  out.i32(m.size.x);
  out.i32(m.size.y);
  out.i32(m.size.z);
  out.id("XYZI");
  out.i32(int32_t(4 + 4 * m.voxels));
  out.i32(0);
  out.i32(int32_t(m.voxels));
  for (int32_t z = m.first.z; z < m.first.z + m.size.z; ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = m.first.y; y < m.first.y + m.size.y; ++y) {
      forRowVoxels(grid, y, z, m.first.x, m.first.x + m.size.x,
                   [&](int32_t x) { out.voxel(x - m.first.x, y - m.first.y, z - m.first.z); });
    }
  }
  return out.flush();
}

}  // namespace

std::vector<MagicaVoxelModel> planMagicaVoxel(const VoxelGrid& grid) {
  constexpr int32_t s = kMagicaVoxelModelSize;
  const int32_t bx = blocksAlong(grid.nx()), by = blocksAlong(grid.ny()), bz = blocksAlong(grid.nz());
  std::vector<int64_t> counts(size_t(bx) * size_t(by) * size_t(bz), 0);
  for (int32_t z = 0; z < grid.nz(); ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      const size_t base = size_t(bx) * (size_t(y / s) + size_t(by) * size_t(z / s));
      for (int32_t b = 0; b < bx; ++b)
        counts[base + size_t(b)] += countRow(grid, y, z, b * s, std::min(grid.nx(), (b + 1) * s));
    }
  }
  std::vector<MagicaVoxelModel> models;
  for (size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] == 0) continue;
    const glm::ivec3 block(int32_t(i % size_t(bx)), int32_t(i / size_t(bx) % size_t(by)),
                           int32_t(i / (size_t(bx) * size_t(by))));
    const glm::ivec3 first = block * s;
    const glm::ivec3 size = glm::min(glm::ivec3(grid.nx(), grid.ny(), grid.nz()) - first, glm::ivec3(s));
    models.push_back(MagicaVoxelModel{first, size, counts[i]});
  }
  if (models.empty()) {
    models.push_back(
        MagicaVoxelModel{glm::ivec3(0), glm::min(glm::ivec3(grid.nx(), grid.ny(), grid.nz()), glm::ivec3(s)), 0});
  }
  return models;
}

uint64_t magicaVoxelFileBytes(const std::vector<MagicaVoxelModel>& models) {
  return 8 + kChunkHeader + childrenBytes(models, sceneGraph(models).size());
}

Status writeMagicaVoxel(const VoxelGrid& grid, ByteSink& sink, const ProgressFn& progress) {
  if (grid.empty()) return makeError(ErrorCode::kInvalidArgument, "there is no grid to write");
  const std::vector<MagicaVoxelModel> models = planMagicaVoxel(grid);
  const std::vector<uint8_t> scene = sceneGraph(models);
  const uint64_t children = childrenBytes(models, scene.size());
  if (children > uint64_t(std::numeric_limits<int32_t>::max())) {
    int64_t filled = 0;
    for (const MagicaVoxelModel& m : models) filled += m.voxels;
    return makeError(ErrorCode::kLimit, std::to_string(filled) + " filled voxels need " + formatBytes(children) +
                                            " as MagicaVoxel models, more than the 2 GiB a .vox file can hold "
                                            "(its chunk sizes are 32-bit); export .vdb or .vti, or voxelize coarser");
  }
  Emitter out(&sink);
  out.id("VOX ");
  out.i32(kVersion);
  out.id("MAIN");
  out.i32(0);
  out.i32(int32_t(children));
  for (size_t i = 0; i < models.size(); ++i) {
    if (Status s = writeModel(grid, models[i], out); !s) return s;
    if (progress && !progress(double(i + 1) / double(models.size())))
      return makeError(ErrorCode::kCancelled, "cancelled");
  }
  out.bytes.insert(out.bytes.end(), scene.begin(), scene.end());
  out.chunk("RGBA", palette());
  return out.flush();
}

Result<std::vector<uint8_t>> encodeMagicaVoxel(const VoxelGrid& grid, const ProgressFn& progress) {
  VectorSink sink;
  if (Status s = writeMagicaVoxel(grid, sink, progress); !s) return s.error();
  return std::move(sink.bytes);
}

}  // namespace vox::io
