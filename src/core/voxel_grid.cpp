#include "vox/core/voxel_grid.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <iterator>
#include <mutex>
#include <vector>

#include "vox/core/bits.h"

namespace vox {

glm::ivec3 directionStep(Direction d) {
  switch (d) {
    case Direction::kYMinus:
      return {0, -1, 0};
    case Direction::kXMinus:
      return {-1, 0, 0};
    case Direction::kXPlus:
      return {1, 0, 0};
    case Direction::kYPlus:
      return {0, 1, 0};
    case Direction::kZMinus:
      return {0, 0, -1};
    case Direction::kZPlus:
      return {0, 0, 1};
  }
  return {0, 0, 0};
}

VoxelGrid::VoxelGrid(Dims dims, GridFrame frame) : dims_(dims), frame_(std::move(frame)) {
  assert(dims.nx >= 1 && dims.ny >= 1 && dims.nz >= 1);
  assert(dims.nx <= kMaxDim && dims.ny <= kMaxDim && dims.nz <= kMaxDim);
  words_per_row_ = (int64_t(dims.nx) + 2 + 63) / 64;
  zero_layer_ = std::make_shared<Layer>(size_t(wordsPerLayer()));
  layers_.assign(size_t(dims.nz) + 2, zero_layer_);
}

namespace {

// Freed layers of at least kMinWords words, kept for reuse up to kCapBytes in all (oldest dropped first): the
// memory of a grid freed after an operation serves the next one's result instead of going back to the system and
// being faulted in again page by page.
class LayerPool {
 public:
  static constexpr size_t kMinWords = 4096;  // 32 KiB: smaller layers are malloc's business
  static constexpr size_t kCapBytes = size_t(256) << 20;
  uint64_t* take(size_t words) {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = free_.rbegin(); it != free_.rend(); ++it) {
      if (it->words != words) continue;
      uint64_t* p = it->p;
      bytes_ -= words * sizeof(uint64_t);
      free_.erase(std::next(it).base());
      return p;
    }
    return nullptr;
  }
  // True when the pool keeps p; false when the caller frees it.
  bool give(uint64_t* p, size_t words) {
    const size_t b = words * sizeof(uint64_t);
    if (words < kMinWords || b > kCapBytes) return false;
    std::vector<uint64_t*> dropped;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      while (bytes_ + b > kCapBytes) {
        dropped.push_back(free_.front().p);
        bytes_ -= free_.front().words * sizeof(uint64_t);
        free_.pop_front();
      }
      free_.push_back(Entry{p, words});
      bytes_ += b;
    }
    for (uint64_t* q : dropped) std::free(q);
    return true;
  }

 private:
  struct Entry {
    uint64_t* p;
    size_t words;
  };
  std::mutex mutex_;
  std::deque<Entry> free_;
  size_t bytes_ = 0;
};

LayerPool& layerPool() {
  static auto* pool = new LayerPool;  // never destroyed: grids held in statics free their layers after main
  return *pool;
}

}  // namespace

uint64_t* VoxelGrid::allocateLayerWords(size_t words, LayerFill fill) {
  if (fill != LayerFill::kSparseZero) {
    if (uint64_t* p = layerPool().take(words)) {
      if (fill == LayerFill::kDenseZero) std::memset(p, 0, words * sizeof(uint64_t));
      return p;
    }
  }
  void* p =
      fill == LayerFill::kOverwritten ? std::malloc(words * sizeof(uint64_t)) : std::calloc(words, sizeof(uint64_t));
  if (!p) throw std::bad_alloc();
  return static_cast<uint64_t*>(p);
}

void VoxelGrid::releaseLayerWords(uint64_t* p, size_t words, LayerFill fill) {
  if (fill == LayerFill::kSparseZero || !layerPool().give(p, words)) std::free(p);
}

glm::ivec3 VoxelGrid::coordinates(int64_t index) const {
  const int64_t nx = dims_.nx, ny = dims_.ny;
  return {int32_t(index % nx), int32_t((index / nx) % ny), int32_t(index / (nx * ny))};
}

uint64_t* VoxelGrid::mutableLayerWords(int32_t z) {
  assert(z >= 0 && z < dims_.nz);
  auto& layer = layers_[size_t(z) + 1];
  if (layer == zero_layer_) {
    layer = std::make_shared<Layer>(size_t(wordsPerLayer()));
  } else if (layer.use_count() > 1) {
    layer = std::make_shared<Layer>(*layer);  // copy on write: another snapshot still holds the old data
  }
  return layer->data();
}

uint64_t* VoxelGrid::freshLayerWords(int32_t z) {
  assert(z >= 0 && z < dims_.nz);
  auto& layer = layers_[size_t(z) + 1];
  layer = std::make_shared<Layer>(size_t(wordsPerLayer()), LayerAllocator<uint64_t>(LayerFill::kDenseZero));
  return layer->data();
}

uint64_t* VoxelGrid::mutableRowWords(int32_t y, int32_t z) {
  assert(y >= 0 && y < dims_.ny);
  return mutableLayerWords(z) + (int64_t(y) + 1) * words_per_row_;
}

void VoxelGrid::set(int64_t x, int64_t y, int64_t z, bool filled) {
  assert(inBounds(x, y, z));
  if (!filled && !layerAllocated(int32_t(z))) return;  // already empty: do not allocate
  uint64_t* row = mutableRowWords(int32_t(y), int32_t(z));
  const int64_t xp = x + 1;
  const uint64_t bit = uint64_t(1) << (xp & 63);
  if (filled) {
    row[xp >> 6] |= bit;
  } else {
    row[xp >> 6] &= ~bit;
  }
}

namespace {

// Sets voxels x0 <= x < x1 (clamped to [0, nx)) of one padded row laid out as in VoxelGrid (bit x + 1), with word
// operations.
void fillRowBits(uint64_t* row, int64_t nx, int64_t x0, int64_t x1) {
  x0 = std::max<int64_t>(x0, 0);
  x1 = std::min<int64_t>(x1, nx);
  if (x0 >= x1) return;
  const int64_t b0 = x0 + 1, b1 = x1 + 1;  // padded bits [b0, b1)
  const int64_t w0 = b0 >> 6, w1 = (b1 - 1) >> 6;
  const uint64_t first = ~uint64_t(0) << (b0 & 63);
  const uint64_t last = ~uint64_t(0) >> (63 - ((b1 - 1) & 63));
  if (w0 == w1) {
    row[w0] |= first & last;
    return;
  }
  row[w0] |= first;
  for (int64_t w = w0 + 1; w < w1; ++w) row[w] = ~uint64_t(0);
  row[w1] |= last;
}

}  // namespace

void VoxelGrid::fillRun(int32_t y, int32_t z, int64_t x0, int64_t x1) {
  if (std::max<int64_t>(x0, 0) >= std::min<int64_t>(x1, dims_.nx)) return;  // nothing to fill: do not allocate
  fillRowBits(mutableRowWords(y, z), dims_.nx, x0, x1);
}

uint8_t VoxelGrid::neighbourCode(int64_t x, int64_t y, int64_t z) const {
  return uint8_t((get(x, y - 1, z) ? 32 : 0) | (get(x - 1, y, z) ? 16 : 0) | (get(x + 1, y, z) ? 8 : 0) |
                 (get(x, y + 1, z) ? 4 : 0) | (get(x, y, z - 1) ? 2 : 0) | (get(x, y, z + 1) ? 1 : 0));
}

std::optional<glm::ivec3> VoxelGrid::neighbourAt(glm::ivec3 voxel, Direction d, int32_t distance) const {
  const glm::ivec3 step = directionStep(d);
  const int64_t x = int64_t(voxel.x) + int64_t(step.x) * distance;
  const int64_t y = int64_t(voxel.y) + int64_t(step.y) * distance;
  const int64_t z = int64_t(voxel.z) + int64_t(step.z) * distance;
  if (!inBounds(x, y, z)) return std::nullopt;
  return glm::ivec3(int32_t(x), int32_t(y), int32_t(z));
}

void VoxelGrid::clear() { std::fill(layers_.begin(), layers_.end(), zero_layer_); }

int64_t VoxelGrid::filledCount() const {
  int64_t n = 0;
  for (int32_t z = 0; z < dims_.nz; ++z) {
    if (!layerAllocated(z)) continue;
    n += popcountWords(layerWords(z), wordsPerLayer());
  }
  return n;
}

size_t VoxelGrid::memoryBytes() const {
  size_t bytes = sizeof(*this) + layers_.capacity() * sizeof(layers_[0]);
  if (zero_layer_) bytes += zero_layer_->size() * sizeof(uint64_t);
  for (const auto& l : layers_) {
    if (l != zero_layer_) bytes += l->size() * sizeof(uint64_t);
  }
  return bytes;
}

int64_t VoxelGrid::allocatedLayers() const {
  return std::count_if(layers_.begin(), layers_.end(), [&](const auto& l) { return l != zero_layer_; });
}

void VoxelGrid::releaseEmptyLayers() {
  for (auto& l : layers_) {
    if (l == zero_layer_) continue;
    if (std::all_of(l->begin(), l->end(), [](uint64_t w) { return w == 0; })) l = zero_layer_;
  }
}

void VoxelGrid::releaseLayer(int32_t z) {
  assert(z >= 0 && z < dims_.nz);
  layers_[size_t(z) + 1] = zero_layer_;
}

bool VoxelGrid::sharesLayerWith(const VoxelGrid& other, int32_t z) const {
  return layers_[size_t(z) + 1] == other.layers_[size_t(z) + 1];
}

bool VoxelGrid::sameVoxels(const VoxelGrid& other) const {
  if (dims_ != other.dims_) return false;
  const auto words = size_t(wordsPerLayer());
  for (int32_t z = 0; z < nz(); ++z) {
    if (sharesLayerWith(other, z)) continue;
    // padding bits are zero in both (rowWords), so whole layers compare
    if (std::memcmp(layerWords(z), other.layerWords(z), words * sizeof(uint64_t)) != 0) return false;
  }
  return true;
}

uint64_t estimateGridBytes(const Dims& dims) {
  const uint64_t wpr = (uint64_t(dims.nx) + 2 + 63) / 64;
  const uint64_t layer = wpr * (uint64_t(dims.ny) + 2) * 8;
  return layer * (uint64_t(dims.nz) + 1) + (uint64_t(dims.nz) + 2) * 16;
}

int64_t cellDistance(const glm::ivec3& a, const glm::ivec3& b) {
  return std::llabs(int64_t(a.x) - b.x) + std::llabs(int64_t(a.y) - b.y) + std::llabs(int64_t(a.z) - b.z);
}

int64_t chebyshevDistance(const glm::ivec3& a, const glm::ivec3& b) {
  return std::max({std::llabs(int64_t(a.x) - b.x), std::llabs(int64_t(a.y) - b.y), std::llabs(int64_t(a.z) - b.z)});
}

}  // namespace vox

namespace vox {

void VoxelGrid::shareLayerFrom(const VoxelGrid& other, int32_t z) {
  assert(other.dims_ == dims_ && z >= 0 && z < dims_.nz);
  layers_[size_t(z + 1)] = other.layerAllocated(z) ? other.layers_[size_t(z + 1)] : zero_layer_;
}

}  // namespace vox
